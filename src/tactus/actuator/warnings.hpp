// What a preset asks of an actuator that it cannot do, and what the engine does instead: at most
// one line (actuator/fit.hpp's note), for stderr or a host's log. Every front end prints it; the
// engine applies the fit itself.
#pragma once

#include <string>
#include <vector>

#include "tactus/actuator/profile.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

std::vector<std::string> actuator_warnings(const ActuatorProfile& actuator,
                                           const Settings& settings);

}  // namespace tactus
