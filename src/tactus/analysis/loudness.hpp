// Short-window K-weighted loudness in dB (LKFS scale): the ITU-R BS.1770-4 K-weighting
// (high shelf + RLB high-pass, coefficients re-derived for any sample rate as in libebur128),
// mean square (a running sum) over a short window instead of BS.1770's 400 ms, so that drum
// hits register within milliseconds. A full-scale 997 Hz sine reads -3.01 dB; doubling amplitude
// adds 6.02 dB.
#pragma once

#include <vector>

#include "tactus/dsp/biquad.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class Loudness {
  public:
    static constexpr double kFloorDb = -120.0;  // reported for silence

    void prepare(const ProcessSpec& spec, double window_ms);  // may allocate
    void reset() noexcept;
    void process(const float* samples, int count) noexcept;  // K-weights and stores squares
    double loudness_db() const noexcept;                     // over the newest window

  private:
    Biquad shelf_, highpass_;
    std::vector<double> squares_;  // ring of K-weighted squares, one window long
    size_t position_ = 0;
    double sum_ = 0.0;  // of squares_, kept running
};

}  // namespace tactus
