#include "tactus/synthesis/envelope.hpp"

#include <cmath>

namespace tactus {
namespace {
constexpr double kDecayRangeDb = 60.0;  // decay_ms is the time to fall this far
constexpr double kSilentLevel = 1e-7;
}  // namespace

void Envelope::set_shape(double attack_ms, double decay_ms, double sustain) noexcept {
    attack_step_ = 1.0 / std::max(1.0, attack_ms * 1e-3 * sample_rate_hz_);
    decay_coefficient_ =
        std::pow(10.0, -kDecayRangeDb / 20.0 / std::max(1.0, decay_ms * 1e-3 * sample_rate_hz_));
    sustain_ = sustain;
}

double Envelope::next() noexcept {
    if (attacking_) {
        level_ += attack_step_;
        if (level_ >= 1.0) level_ = 1.0, attacking_ = false;
        return level_;
    }
    level_ = sustain_ + (level_ - sustain_) * decay_coefficient_;
    if (sustain_ == 0.0 && level_ < kSilentLevel) level_ = 0.0;
    return level_;
}

}  // namespace tactus
