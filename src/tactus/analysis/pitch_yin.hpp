// Fundamental frequency with confidence by YIN (de Cheveigné & Kawahara 2002, JASA 111:1917):
// difference function via FFT autocorrelation, cumulative-mean normalisation, absolute
// threshold, parabolic interpolation. Confidence = 1 - normalised difference at the chosen lag.
// Unvoiced or silent input reads f0 = 0 with its (low) confidence.
#pragma once

#include <vector>

#include "tactus/dsp/process_spec.hpp"
#include "tactus/dsp/real_fft.hpp"
#include "tactus/dsp/sample_history.hpp"

namespace tactus {

struct Pitch {
    double f0_hz = 0;
    double confidence = 0;
};

// The pitch range searched and the YIN absolute threshold.
struct PitchSettings {
    double min_hz = 50;
    double max_hz = 1500;
    double threshold = 0.15;
};

class PitchYin {
  public:
    void prepare(const ProcessSpec& spec, const PitchSettings& settings);  // may allocate
    // Live (audio thread): the YIN absolute threshold.
    void set_threshold(double threshold) noexcept { threshold_ = threshold; }
    Pitch analyse(const SampleHistory& history) noexcept;
    // Samples of history analyse() reads.
    int span_samples() const { return 2 * window_; }

  private:
    double sample_rate_hz_ = 0, threshold_ = 0.15;
    int window_ = 0, min_lag_ = 0, max_lag_ = 0;
    RealFft fft_;
    std::vector<float> signal_;
    std::vector<std::complex<float>> signal_spectrum_;
    std::vector<double> difference_;
};

}  // namespace tactus
