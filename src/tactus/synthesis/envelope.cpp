#include "tactus/synthesis/envelope.hpp"

#include <cmath>

namespace tactus {
namespace {
constexpr double kDecayRangeDb = 60.0;  // decay_ms is the time to fall this far
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

}  // namespace tactus
