#include "tactus/synthesis/voice.hpp"

namespace tactus {
namespace {
constexpr double kGlideMs = 1.0;
constexpr double kQuietEnvelope = 1e-3;  // -60 dB: restarting the phase here cannot click
}  // namespace

void Voice::prepare(const ProcessSpec& spec, double harmonic_limit_hz) {
    oscillator_.prepare(spec, harmonic_limit_hz);
    envelope_.prepare(spec);
    flutter_.prepare(spec);
    pressure_.prepare(spec);
    glide_.prepare(spec, kGlideMs);
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

void Voice::process(float* out, int count) noexcept {
    double amplitude = amplitude_, frequency = frequency_hz_, mix = square_mix_;
    const Glide glide = glide_;
    for (int i = 0; i < count; ++i) {
        const double level = envelope_.next();
        // Silent here and at the next sample: the oscillator can wait (it restarts at a trigger).
        out[i] = level == 0.0 && envelope_.level() == 0.0
                     ? 0.0f
                     : static_cast<float>(
                           amplitude * level *
                           oscillator_.next(glide.mean(frequency, target_.frequency_hz), mix));
        amplitude = glide.step(amplitude, target_.amplitude);
        frequency = glide.step(frequency, target_.frequency_hz);
        mix = glide.step(mix, target_.square_mix);
    }
    amplitude_ = amplitude;
    frequency_hz_ = frequency;
    square_mix_ = mix;
}

void Voice::process(float* carrier, float* flutter, float* pressure, int count) noexcept {
    process(carrier, count);
    if (flutter) flutter_.process(flutter, count);
    if (pressure) pressure_.process(pressure, count);
}

}  // namespace tactus
