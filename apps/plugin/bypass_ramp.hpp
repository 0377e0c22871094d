// The plugin's bypass: the vibration fades out (and back in) over kRampMs instead of stopping
// on a sample, which an actuator would render as a click. The engine keeps running while
// bypassed, so it comes back with its analysis current. Real-time safe.
#pragma once

#include <algorithm>

namespace tactus::plugin {

class BypassRamp {
  public:
    static constexpr double kRampMs = 20;

    void prepare(double sample_rate_hz) {
        step_ = static_cast<float>(1.0 / std::max(1.0, kRampMs * 1e-3 * sample_rate_hz));
    }
    void reset(bool bypassed) noexcept { gain_ = bypassed ? 0.0f : 1.0f; }
    float gain() const noexcept { return gain_; }

    // Scales `channels` buffers of `count` samples by the ramp towards 0 (bypassed) or 1.
    void process(float* const* buffers, int channels, int count, bool bypassed) noexcept {
        const float target = bypassed ? 0.0f : 1.0f;
        if (gain_ == target && target == 1.0f) return;
        const float step = bypassed ? -step_ : step_;
        float g = gain_;
        for (int i = 0; i < count; ++i) {
            g = std::clamp(g + step, 0.0f, 1.0f);
            for (int c = 0; c < channels; ++c) buffers[c][i] *= g;
        }
        gain_ = g;
    }

  private:
    float gain_ = 1.0f, step_ = 1.0f;
};

}  // namespace tactus::plugin
