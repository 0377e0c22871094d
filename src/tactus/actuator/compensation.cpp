#include "tactus/actuator/compensation.hpp"

#include <algorithm>

namespace tactus {

double ActuatorCompensation::target_db(double frequency_hz) const {
    const double f = std::clamp(frequency_hz, actuator_.band_low_hz, actuator_.band_high_hz);
    return std::clamp(-actuator_.response_db(f), -kBoundDb, kBoundDb);
}

void ActuatorCompensation::prepare(double sample_rate_hz, const ActuatorProfile& actuator) {
    actuator_ = actuator;
    eq_.design(sample_rate_hz, std::max(actuator.band_low_hz, 1.0), actuator.band_high_hz,
               [this](double f) { return target_db(f); });
}

}  // namespace tactus
