#include "tactus/post/post_chain.hpp"

#include <algorithm>

#include "tactus/core/units.hpp"

namespace tactus {

void PostChain::prepare(double sample_rate_hz, const Settings& s, const ActuatorProfile* actuator) {
    const double low_hz = s[P::post_band_low_hz], high_hz = s[P::post_band_high_hz];
    first_band_.prepare(sample_rate_hz, low_hz, high_hz, kFirstBandOrder);
    flatten_.prepare(sample_rate_hz, low_hz, high_hz,
                     {.strength = s[P::post_flatten_strength],
                      .range_db = s[P::post_flatten_range_db],
                      .contact_area_cm2 = s[P::perception_contact_area_cm2],
                      .level_db = s[P::post_flatten_level_db]});
    compensate_ = actuator != nullptr;
    if (actuator) compensation_.prepare(sample_rate_hz, *actuator);
    ceiling_ = db_to_gain(s[P::post_ceiling_db]);
    if (actuator) ceiling_ = std::min(ceiling_, actuator->max_drive);
    limiter_.prepare(sample_rate_hz, s[P::post_lookahead_ms], s[P::post_release_ms],
                     s[P::post_drive_db], s[P::post_limiter_threshold_db],
                     ceiling_ * db_to_gain(-kRingingMarginDb));
    last_band_.prepare(sample_rate_hz, low_hz, high_hz, kLastBandOrder);
    reset();
}

void PostChain::reset() noexcept {
    first_band_.reset();
    flatten_.reset();
    compensation_.reset();
    limiter_.reset();
    last_band_.reset();
    clipped_ = 0;
}

void PostChain::process(float* samples, int count) noexcept {
    first_band_.process(samples, count);
    flatten_.process(samples, count);
    if (compensate_) compensation_.process(samples, count);
    limiter_.process(samples, count);
    last_band_.process(samples, count);
    const float ceiling = float_at_most(ceiling_);
    for (int i = 0; i < count; ++i) {
        if (samples[i] > ceiling)
            samples[i] = ceiling, ++clipped_;
        else if (samples[i] < -ceiling)
            samples[i] = -ceiling, ++clipped_;
    }
}

}  // namespace tactus
