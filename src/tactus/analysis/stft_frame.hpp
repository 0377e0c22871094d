// One windowed STFT frame of the newest input samples: periodic Hann window, magnitude spectrum
// scaled so that a full-scale sine centred on a bin reads 1.
#pragma once

#include <vector>

#include "tactus/dsp/real_fft.hpp"
#include "tactus/dsp/sample_history.hpp"

namespace tactus {

class StftFrame {
  public:
    void prepare(int window_samples, double sample_rate_hz);  // may allocate
    void analyse(const SampleHistory& history) noexcept;      // fills magnitudes()

    int window_samples() const { return fft_.size(); }
    int bins() const { return fft_.bins(); }
    double bin_hz() const { return bin_hz_; }
    const std::vector<float>& magnitudes() const { return magnitudes_; }
    const std::vector<float>& powers() const { return powers_; }

  private:
    RealFft fft_;
    std::vector<float> window_;
    std::vector<float> magnitudes_, powers_;
    double bin_hz_ = 0;
};

}  // namespace tactus
