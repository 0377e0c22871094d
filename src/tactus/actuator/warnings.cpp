#include "tactus/actuator/warnings.hpp"

#include "tactus/actuator/fit.hpp"

namespace tactus {

std::vector<std::string> actuator_warnings(const ActuatorProfile& actuator,
                                           const Settings& settings) {
    std::string note = fit_to_actuator(actuator, settings).note;
    if (note.empty()) return {};
    return {std::move(note)};
}

}  // namespace tactus
