#include "tactus/engine/actuator_chain.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/dsp/clip.hpp"

namespace tactus {

void ActuatorChain::prepare(const ProcessSpec& spec, int rate_divisor, const Settings& settings,
                            const ActuatorProfile* profile) {
    const ProcessSpec internal = Upsampler::internal_spec(spec, rate_divisor);
    upsampler_.prepare(spec, rate_divisor);
    // The upsampler's delay comes out of the limiter's look-ahead (down to the shortest allowed).
    Settings post_settings = settings;
    const double upsampler_delay_ms = 1e3 * upsampler_.delay_samples() / spec.sample_rate_hz;
    post_settings.set(P::post_lookahead_ms,
                      std::max(tactus::spec(P::post_lookahead_ms).min,
                               settings[P::post_lookahead_ms] - upsampler_delay_ms));
    post_.prepare(internal, post_settings, profile);
    const auto block = static_cast<size_t>(internal.max_block);
    carrier_.assign(block, 0.0f);
    flutter_.assign(block, 0.0f);
    pressure_.assign(block, 0.0f);
    ceiling_ = clip_ceiling_ = float_at_most(post_.ceiling());
    reset();
}

void ActuatorChain::reset() noexcept {
    post_.reset();
    upsampler_.reset();
    clipped_ = 0;
}

void ActuatorChain::set_live(const Settings& settings, int glide_samples) noexcept {
    post_.set_live(settings, glide_samples);
    const float ceiling = float_at_most(post_.ceiling());
    clip_ceiling_ = std::max(ceiling_, ceiling);
    ceiling_ = ceiling;
}

void ActuatorChain::process(float* carrier, float* flutter, const float* pressure,
                            int internal_count, bool in_place, float* out, int count) noexcept {
    const auto n = static_cast<size_t>(internal_count);
    if (!in_place) {
        carrier = std::copy_n(carrier, n, carrier_.data()) - n;
        if (flutter) flutter = std::copy_n(flutter, n, flutter_.data()) - n;
    }
    if (pressure && pressure_scale_ != 1.0) {
        for (size_t i = 0; i < n; ++i)
            pressure_[i] = static_cast<float>(pressure[i] * pressure_scale_);
        pressure = pressure_.data();
    }
    post_.process(carrier, flutter, pressure, internal_count);
    if (upsampler_.factor() == 1) {
        std::copy_n(carrier, n, out);  // the post chain's clip was the last
    } else {
        upsampler_.process(carrier, internal_count, out, count);
        clipped_ += clip(out, count, clip_ceiling_);
    }
    clip_ceiling_ = ceiling_;
}

}  // namespace tactus
