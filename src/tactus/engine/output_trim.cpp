#include "tactus/engine/output_trim.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "tactus/core/units.hpp"

namespace tactus {

void ActuatorOutput::check_gain_db(double gain_db) {
    if (!(gain_db >= kMinGainDb && gain_db <= 0))
        throw std::invalid_argument(
            fmt::format("gain {} dB is outside {} to 0 dB", gain_db, kMinGainDb));
}

void ActuatorOutput::check(int index) const {
    try {
        check_gain_db(gain_db);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format("actuator {}: {}", index, e.what()));
    }
    if (!(delay_ms >= 0 && delay_ms <= kMaxDelayMs))
        throw std::invalid_argument(fmt::format("actuator {}: delay {} ms is outside 0 to {} ms",
                                                index, delay_ms, kMaxDelayMs));
    try {
        check_overlay(overlay);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format("actuator {}: {}", index, e.what()));
    }
}

void ActuatorOutput::check_input(int index, const ProcessSpec& spec) const {
    if (route.kind == Route::Kind::channel && spec.channels > 1 && route.channel >= spec.channels)
        throw std::invalid_argument(
            fmt::format("actuator {}: route {} takes input channel {}; the input has {}", index,
                        route.text(), route.channel + 1, spec.channels));
    if (route.kind == Route::Kind::band && route.high_hz >= 0.5 * spec.sample_rate_hz)
        throw std::invalid_argument(
            fmt::format("actuator {}: route {} reaches past half the sample rate ({:g} Hz)", index,
                        route.text(), spec.sample_rate_hz));
}

void OutputTrim::prepare(const ProcessSpec& spec, const ActuatorOutput& output) {
    const double sample_rate_hz = spec.sample_rate_hz;
    glide_samples_ =
        std::max<int>(1, static_cast<int>(ms_to_samples(kGainGlideMs, sample_rate_hz)));
    gain_target_ = db_to_gain(output.gain_db);
    const auto delay = static_cast<int>(ms_to_samples(output.delay_ms, sample_rate_hz));
    delay_.prepare(1, delay, delay);
    reset();
}

void OutputTrim::reset() noexcept {
    gain_ = gain_target_;
    gain_left_ = 0;
    delay_.reset();
}

void OutputTrim::set_gain_db(double gain_db) noexcept {
    gain_target_ = db_to_gain(gain_db);
    gain_left_ = glide_samples_;
    gain_step_ = (gain_target_ - gain_) / gain_left_;
}

void OutputTrim::process(float* samples, int count) noexcept {
    if (gain_left_ > 0 || gain_ != 1.0) {
        for (int i = 0; i < count; ++i) {
            if (gain_left_ > 0) gain_ = --gain_left_ == 0 ? gain_target_ : gain_ + gain_step_;
            samples[i] = static_cast<float>(samples[i] * gain_);
        }
    }
    if (latency() > 0) delay_.process(&samples, count);
}

}  // namespace tactus
