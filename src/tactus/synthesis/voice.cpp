#include "tactus/synthesis/voice.hpp"

#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {
constexpr double kGlideMs = 1.0;
constexpr double kQuietEnvelope = 1e-3;  // -60 dB: restarting the phase here cannot click
constexpr double kSilentAmplitude = 1e-9;
}  // namespace

void Voice::prepare(double sample_rate_hz, double harmonic_limit_hz) {
    oscillator_.prepare(sample_rate_hz, harmonic_limit_hz);
    envelope_.prepare(sample_rate_hz);
    flutter_.prepare(sample_rate_hz);
    pressure_.prepare(sample_rate_hz);
    glide_ = one_pole_coefficient(kGlideMs, sample_rate_hz);
    glide_mean_ = glide_ > 0.0 ? (1.0 - glide_) / -std::log(glide_) : 0.0;
    reset();
}

void Voice::reset() noexcept {
    oscillator_.reset();
    envelope_.reset();
    flutter_.reset();
    pressure_.reset();
    target_ = {};
    amplitude_ = 0;
    frequency_hz_ = 0;
    square_mix_ = 0;
}

void Voice::apply(const ControlFrame& frame) noexcept {
    target_ = frame;
    flutter_.apply(frame);
    pressure_.apply(frame);
    envelope_.set_shape(frame.attack_ms, frame.decay_ms, frame.sustain);
    if (frame.trigger) {
        if (envelope_.level() < kQuietEnvelope) {
            oscillator_.reset();
            frequency_hz_ = frame.frequency_hz;  // a new pulse starts at its own pitch
            square_mix_ = frame.square_mix;
        }
        envelope_.trigger();
    }
}

void Voice::render(float* out, int count) noexcept {
    double amplitude = amplitude_, frequency = frequency_hz_, mix = square_mix_;
    const double g = glide_;
    for (int i = 0; i < count; ++i) {  // this sample's values, then one glide step
        const double level = envelope_.next();
        const double mean_frequency =
            target_.frequency_hz + glide_mean_ * (frequency - target_.frequency_hz);
        // Silent here and at the next sample: the oscillator can wait (it restarts at a trigger).
        out[i] =
            level == 0.0 && envelope_.level() == 0.0
                ? 0.0f
                : static_cast<float>(amplitude * level * oscillator_.next(mean_frequency, mix));
        amplitude = target_.amplitude + g * (amplitude - target_.amplitude);
        if (target_.amplitude == 0.0 && amplitude < kSilentAmplitude) amplitude = 0.0;
        frequency = target_.frequency_hz + g * (frequency - target_.frequency_hz);
        mix = target_.square_mix + g * (mix - target_.square_mix);
    }
    amplitude_ = amplitude;
    frequency_hz_ = frequency;
    square_mix_ = mix;
}

void Voice::render(float* carrier, float* flutter, float* pressure, int count) noexcept {
    render(carrier, count);
    if (flutter) flutter_.render(flutter, count);
    if (pressure) pressure_.render(pressure, count);
}

}  // namespace tactus
