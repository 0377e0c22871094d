#include "tactus/post/post_chain.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/actuator/actuator_model.hpp"
#include "tactus/core/units.hpp"
#include "tactus/dsp/clip.hpp"
#include "tactus/params/components.hpp"
#include "tactus/post/flattening_inputs.hpp"

namespace tactus {
namespace {
// NPI's "notch at 30 Hz" (paper Table 1 note 3, §5.2 note 4); its width spans the prime
// sensitivity range 25-40 Hz: Q = 30 / (40 - 25) = 2.
constexpr double kFlutterPeakHz = 30.0;
constexpr double kFlutterPeakQ = 2.0;
// With the flutter on, the last high-pass (1 Hz) rings for seconds after the sound stops; below
// -180 dBFS its output is set to 0, so silence still ends in exact zeros.
constexpr float kSilentOutput = 1e-9f;

}  // namespace

void PostChain::prepare(const ProcessSpec& spec, const Settings& s,
                        const ActuatorProfile* actuator) {
    const double sample_rate_hz = spec.sample_rate_hz;
    const double low_hz = s[P::post_band_low_hz], high_hz = s[P::post_band_high_hz];
    sample_rate_hz_ = sample_rate_hz;
    flutter_on_ = flutter_enabled(s);
    pressure_on_ = pressure_enabled(s);
    flatten_.prepare(spec, flattening_inputs(s));
    erm_ = actuator != nullptr && actuator->type == ActuatorType::erm;
    compensate_ = actuator != nullptr && !erm_;
    // The carrier has no partial above the band (synthesis/oscillator.hpp): without an actuator
    // the first band-limit is a high-pass, as a low-pass would only delay every pulse (0.8 ms at
    // 8th order). An actuator's compensation lifts the envelope's sidebands just above a narrow
    // band (an LRA's) by up to its bound: the low-pass keeps them out.
    first_band_.prepare(
        spec,
        {.low_hz = low_hz, .high_hz = high_hz, .order = kFirstBandOrder, .low_pass = compensate_});
    if (compensate_) compensation_.prepare(spec, *actuator);
    if (erm_) erm_drive_.prepare(spec, erm_spin_time_constant_ms(*actuator));
    max_drive_ = actuator ? actuator->max_drive : 1.0;
    limiter_.prepare(spec, s[P::post_lookahead_ms], {});
    set_live(s, 0);
    last_band_.prepare(spec, {.low_hz = flutter_on_ ? s[P::post_flutter_low_hz] : low_hz,
                              .high_hz = high_hz,
                              .order = kLastBandOrder});
    reset();
}

FlatteningFilter::Design flattening_design(double sample_rate_hz, const Settings& s) {
    return FlatteningFilter::design(sample_rate_hz, flattening_inputs(s));
}

void PostChain::set_live(const Settings& s, int glide_samples) noexcept {
    flutter_peak_on_ = flutter_on_ && s[P::post_flutter_peak_db] != 0.0;
    flutter_peak_.set(BiquadCoefficients::peaking(kFlutterPeakHz, kFlutterPeakQ,
                                                  s[P::post_flutter_peak_db], sample_rate_hz_));
    const double ceiling = ceiling_for(s);
    clip_ceiling_ = glide_samples > 0 ? std::max(ceiling, ceiling_) : ceiling;
    ceiling_ = ceiling;
    const double pressure_headroom = pressure_on_ ? s[P::pressure_weight] * ceiling_ : 0.0;
    limiter_.set_levels({.drive_db = s[P::post_drive_db],
                         .threshold_db = s[P::post_limiter_threshold_db],
                         .ceiling = (ceiling_ - pressure_headroom) * db_to_gain(-kRingingMarginDb),
                         .release_ms = s[P::post_release_ms]},
                        glide_samples);
}

void PostChain::reset() noexcept {
    first_band_.reset();
    flatten_.reset();
    flutter_peak_.reset();
    compensation_.reset();
    erm_drive_.reset();
    limiter_.reset();
    last_band_.reset();
    clipped_ = 0;
}

void PostChain::process(float* samples, float* flutter, const float* pressure, int count) noexcept {
    first_band_.process(samples, count);
    if (erm_) {
        limiter_.process(samples, count);
        erm_drive_.process(samples, count, float_at_most(ceiling_));
        clipped_ += clip(samples, count, float_at_most(clip_ceiling_));
        clip_ceiling_ = ceiling_;
        return;
    }
    flatten_.process(samples, count);
    if (flutter_on_ && flutter) {
        if (flutter_peak_on_)
            for (int i = 0; i < count; ++i)
                flutter[i] = static_cast<float>(flutter_peak_.process(flutter[i]));
        for (int i = 0; i < count; ++i) samples[i] += flutter[i];
    }
    if (compensate_) compensation_.process(samples, count);
    limiter_.process(samples, count);
    last_band_.process(samples, count);
    if (flutter_on_)
        for (int i = 0; i < count; ++i)
            if (std::abs(samples[i]) < kSilentOutput) samples[i] = 0.0f;
    if (pressure_on_ && pressure)
        for (int i = 0; i < count; ++i) samples[i] += pressure[i];
    clipped_ += clip(samples, count, float_at_most(clip_ceiling_));
    clip_ceiling_ = ceiling_;
}

}  // namespace tactus
