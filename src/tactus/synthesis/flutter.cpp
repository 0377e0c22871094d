#include "tactus/synthesis/flutter.hpp"

#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {
constexpr double kNpiHighHz = perception::info(perception::Channel::NPI).range_high_hz;
}  // namespace

void Flutter::prepare(const ProcessSpec& spec) {
    oscillator_.prepare(spec, kNpiHighHz);
    glide_.prepare(spec, corner_time_constant_ms(kNpiHighHz));
    reset();
}

void Flutter::reset() noexcept {
    oscillator_.reset();
    amplitude_ = rate_hz_ = square_mix_ = 0;
    target_amplitude_ = target_rate_hz_ = target_square_mix_ = 0;
}

void Flutter::apply(const ControlFrame& frame) noexcept {
    if (amplitude_ == 0.0 && frame.flutter_amplitude > 0.0) {
        oscillator_.reset();  // a flutter rising from silence starts at its own rate, phase 0
        rate_hz_ = frame.flutter_hz;
        square_mix_ = frame.square_mix;
    }
    target_amplitude_ = frame.flutter_amplitude;
    target_rate_hz_ = frame.flutter_hz;
    target_square_mix_ = frame.square_mix;
}

void Flutter::process(float* out, int count) noexcept {
    double amplitude = amplitude_, rate = rate_hz_, mix = square_mix_;
    const Glide glide = glide_;
    for (int i = 0; i < count; ++i) {
        // Silent and staying silent: the oscillator can wait (it restarts on the way up).
        out[i] = amplitude == 0.0 && target_amplitude_ == 0.0
                     ? 0.0f
                     : static_cast<float>(amplitude *
                                          oscillator_.next(glide.mean(rate, target_rate_hz_), mix));
        amplitude = glide.step(amplitude, target_amplitude_);
        rate = glide.step(rate, target_rate_hz_);
        mix = glide.step(mix, target_square_mix_);
    }
    amplitude_ = amplitude;
    rate_hz_ = rate;
    square_mix_ = mix;
}

}  // namespace tactus
