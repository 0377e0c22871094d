// DC blocker in front of the spectral features: y[n] = x[n] - x[n-1] + r y[n-1], a one-zero,
// one-pole high-pass with its -3 dB corner at kCornerHz (r = exp(-2 pi fc / fs)). A DC offset in
// a recording (cheap converters, a badly centred mix) would otherwise pile energy into the lowest
// STFT bins and pull the spectral centroid, and so the vibration frequency, towards 0 Hz.
// Loudness needs no blocker: its K-weighting already high-passes (ITU-R BS.1770).
#pragma once

#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class DcBlocker {
  public:
    static constexpr double kCornerHz = 10.0;  // below every feature's band (pitch.min_hz >= 30)

    void prepare(const ProcessSpec& spec) {
        pole_ = static_cast<float>(std::exp(-2.0 * kPi * kCornerHz / spec.sample_rate_hz));
        reset();
    }
    void reset() noexcept { previous_in_ = previous_out_ = 0.0f; }
    int latency() const { return 0; }
    // In place; count samples.
    void process(float* samples, int count) noexcept {
        float x1 = previous_in_, y1 = previous_out_;
        for (int i = 0; i < count; ++i) {
            const float x = samples[i];
            y1 = x - x1 + pole_ * y1;
            x1 = x;
            samples[i] = y1;
        }
        previous_in_ = x1;
        previous_out_ = y1;
    }

  private:
    float pole_ = 0.0f, previous_in_ = 0.0f, previous_out_ = 0.0f;
};

}  // namespace tactus
