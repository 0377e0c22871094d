// What a preset asks of an actuator that it cannot do: one line each, for stderr. The preset's
// vibration frequencies outside the usable band (e.g. 40 Hz on a 175 Hz LRA), pressure-range
// content (NPIII, 0.4-3 Hz, paper §5.4) without DC capability, an ERM's frequency tied to its
// drive, attacks faster than the actuator rises, a drive above its maximum.
#pragma once

#include <string>
#include <vector>

#include "tactus/actuator/profile.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

std::vector<std::string> actuator_warnings(const ActuatorProfile& actuator,
                                           const Settings& settings);

}  // namespace tactus
