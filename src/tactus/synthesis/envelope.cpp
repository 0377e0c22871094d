#include "tactus/synthesis/envelope.hpp"

#include <cmath>

namespace tactus {
namespace {
constexpr double kDecayRangeDb = 60.0;  // decay_ms is the time to fall this far
constexpr double kSilentLevel = 1e-7;
}  // namespace

void Envelope::set_shape(double attack_ms, double decay_ms, double sustain) noexcept {
    sustain_ = sustain;
    if (attack_ms == shaped_attack_ms_ && decay_ms == shaped_decay_ms_) return;  // no pow again
    shaped_attack_ms_ = attack_ms;
    shaped_decay_ms_ = decay_ms;
    attack_step_ = 1.0 / std::max(1.0, attack_ms * 1e-3 * sample_rate_hz_);
    decay_coefficient_ =
        std::pow(10.0, -kDecayRangeDb / 20.0 / std::max(1.0, decay_ms * 1e-3 * sample_rate_hz_));
}

// The level at this sample, then one step on: sample n after a trigger is the envelope at time
// n / rate, as the oscillator's sample n is its phase at that time, so the product is the same
// signal at any sample rate.
double Envelope::next() noexcept {
    const double level = level_;
    if (attacking_) {
        level_ += attack_step_;
        if (level_ >= 1.0) {  // the peak fell between samples: decay for the rest of the step
            const double past_peak = (level_ - 1.0) / attack_step_;  // fraction of a step
            level_ = sustain_ + (1.0 - sustain_) * std::pow(decay_coefficient_, past_peak);
            attacking_ = false;
        }
        return level;
    }
    level_ = sustain_ + (level_ - sustain_) * decay_coefficient_;
    if (sustain_ == 0.0 && level_ < kSilentLevel) level_ = 0.0;
    return level;
}

}  // namespace tactus
