#include "tactus/engine/engine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tactus/core/units.hpp"
#include "tactus/dsp/denormals.hpp"
#include "tactus/dsp/clip.hpp"
#include "tactus/params/components.hpp"

namespace tactus {
namespace {

int64_t ceil_div(int64_t a, int64_t b) {
    return (a + b - 1) / b;
}

}  // namespace

void Engine::set_actuator(std::optional<ActuatorProfile> actuator) {
    if (actuator) settings_.set(P::actuator_dc, actuator->dc ? 1.0 : 0.0);
    actuator_ = std::move(actuator);
}

void Engine::check_sample_rate(double sample_rate_hz) {
    if (!(sample_rate_hz >= kMinSampleRateHz && sample_rate_hz <= kMaxSampleRateHz))
        throw std::invalid_argument(
            fmt::format("sample rate {} Hz is outside the supported {}-{} Hz", sample_rate_hz,
                        kMinSampleRateHz, kMaxSampleRateHz));
}

void Engine::prepare(double sample_rate_hz, int max_block) {
    check_sample_rate(sample_rate_hz);
    if (max_block < 1 || max_block > kMaxBlock)
        throw std::invalid_argument(
            fmt::format("block size {} is outside the supported 1-{}", max_block, kMaxBlock));
    sample_rate_hz_ = sample_rate_hz;
    const double band_high_hz = settings_[P::post_band_high_hz];
    const int divisor =
        std::clamp(static_cast<int>(sample_rate_hz / kMinInternalRateHz), 1, Upsampler::kMaxFactor);
    const double internal_rate_hz = sample_rate_hz / divisor;
    const int max_internal_block = static_cast<int>(ceil_div(max_block, divisor)) + 1;
    upsampler_.prepare(divisor, max_internal_block);
    internal_.assign(divisor > 1 ? static_cast<size_t>(max_internal_block) : 0, 0.0f);
    flutter_.assign(flutter_enabled(settings_) ? static_cast<size_t>(max_internal_block) : 0, 0.0f);
    pressure_.assign(pressure_enabled(settings_) ? static_cast<size_t>(max_internal_block) : 0,
                     0.0f);

    // The upsampler's delay comes out of the limiter's look-ahead (down to the shortest allowed).
    Settings post_settings = settings_;
    const double upsampler_delay_ms = 1e3 * upsampler_.delay_samples() / sample_rate_hz;
    post_settings.set(P::post_lookahead_ms,
                      std::max(spec(P::post_lookahead_ms).min,
                               settings_[P::post_lookahead_ms] - upsampler_delay_ms));
    post_.prepare(internal_rate_hz, post_settings, actuator_ ? &*actuator_ : nullptr);
    ceiling_ = float_at_most(post_.ceiling());
    analyzer_.prepare(sample_rate_hz, settings_);
    mapper_.prepare(settings_, sample_rate_hz / analyzer_.hop_samples(), post_.ceiling());
    voice_.prepare(internal_rate_hz, band_high_hz);
    reset();
}

void Engine::reset() noexcept {
    analyzer_.reset();
    mapper_.reset();
    voice_.reset();
    post_.reset();
    upsampler_.reset();
    position_ = 0;
    clipped_ = 0;
}

// The analysis computes what the mapping or the observer reads; the mapping's gate reads the
// loudness.
void Engine::set_observer(FrameObserver* observer) {
    observer_ = observer;
    FeatureSet read = observer ? observer->reads() : FeatureSet::none();
    read.loudness = true;
    for (P source : {P::amplitude_source, P::frequency_source, P::square_mix_source,
                     P::flutter_level_source, P::flutter_rate_source, P::pressure_level_source})
        read = read | group_of(static_cast<FeatureSource>(settings_[source]));
    analyzer_.set_features(read);
}

int Engine::latency() const {
    return post_.latency_samples() * rate_divisor() +
           static_cast<int>(std::lround(upsampler_.delay_samples()));
}

void Engine::process(const float* in, float* out, int count) noexcept {
    const ScopedFlushDenormals no_denormals;
    const int divisor = rate_divisor();
    int done = 0, rendered = 0;  // `in` is read before `out` is written: they may alias
    // At the input rate, synthesis and post-processing write `out` directly (chunk by chunk,
    // after the analyser has read the same samples of `in`), and the post chain's clip is final.
    float* const internal = divisor == 1 ? out : internal_.data();
    float* const flutter = flutter_.empty() ? nullptr : flutter_.data();
    float* const pressure = pressure_.empty() ? nullptr : pressure_.data();
    while (done < count) {
        const int chunk = std::min(count - done, analyzer_.samples_to_next_frame());
        const bool frame_due = analyzer_.write(in + done, chunk);
        // Internal sample k stands at input sample k * divisor.
        const auto due =
            static_cast<int>(ceil_div(position_ + chunk, divisor) - ceil_div(position_, divisor));
        voice_.render(internal + rendered, flutter ? flutter + rendered : nullptr,
                      pressure ? pressure + rendered : nullptr, due);
        rendered += due;
        position_ += chunk;
        if (frame_due) {
            const Features& features = analyzer_.analyse();
            const ControlFrame control = mapper_.map(features);
            voice_.apply(control);
            if (observer_) observer_->on_frame(features, control);
        }
        done += chunk;
    }
    post_.process(internal, flutter, pressure, rendered);
    if (divisor == 1) return;
    upsampler_.process(internal, rendered, out, count);
    clipped_ += clip(out, count, ceiling_);
}

}  // namespace tactus
