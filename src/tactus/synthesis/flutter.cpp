#include "tactus/synthesis/flutter.hpp"

#include "tactus/core/units.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {
constexpr double kNpiHighHz = perception::info(perception::Channel::NPI).range_high_hz;
constexpr double kGlideMs = 1e3 / (2.0 * kPi * kNpiHighHz);
constexpr double kSilentAmplitude = 1e-9;
}  // namespace

void Flutter::prepare(double sample_rate_hz) {
    oscillator_.prepare(sample_rate_hz, kNpiHighHz);
    glide_ = one_pole_coefficient(kGlideMs, sample_rate_hz);
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

void Flutter::render(float* out, int count) noexcept {
    double amplitude = amplitude_, rate = rate_hz_, mix = square_mix_;
    const double g = glide_;
    for (int i = 0; i < count; ++i) {
        amplitude = target_amplitude_ + g * (amplitude - target_amplitude_);
        if (target_amplitude_ == 0.0 && amplitude < kSilentAmplitude) amplitude = 0.0;
        rate = target_rate_hz_ + g * (rate - target_rate_hz_);
        mix = target_square_mix_ + g * (mix - target_square_mix_);
        out[i] =
            amplitude == 0.0 ? 0.0f : static_cast<float>(amplitude * oscillator_.next(rate, mix));
    }
    amplitude_ = amplitude;
    rate_hz_ = rate;
    square_mix_ = mix;
}

}  // namespace tactus
