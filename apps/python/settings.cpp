#include "settings.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "tactus/actuator/warnings.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/layout_file.hpp"
#include "tactus/io/preset.hpp"

namespace py = pybind11;

namespace tactus::python {

P param_named(const std::string& name) {
    if (const auto id = find_param(name)) return *id;
    for (const ParamSpec& s : param_table())
        if (identifier_of(s) == name) return s.param;
    std::string nearest = nearest_param(name);
    if (name.find('.') == std::string::npos) nearest = identifier_of(spec(*find_param(nearest)));
    throw py::value_error(fmt::format("unknown key '{}' (did you mean '{}'?)", name, nearest));
}

double param_value(P id, const py::handle& value) {
    Settings parsed;
    try {
        if (py::isinstance<py::str>(value))
            parsed.set_from_text(id, value.cast<std::string>());
        else if (py::isinstance<py::bool_>(value) || py::isinstance<py::int_>(value) ||
                 py::isinstance<py::float_>(value) || py::hasattr(value, "__float__"))
            parsed.set(id, value.cast<double>());
        else
            throw std::invalid_argument(fmt::format("{} = {} is not a number or a name",
                                                    spec(id).key,
                                                    py::str(value).cast<std::string>()));
    } catch (const std::invalid_argument& e) {
        throw py::value_error(e.what());
    }
    return parsed[id];
}

Settings resolve_settings(const std::string& preset, const py::object& settings,
                          const py::kwargs& params) {
    Settings resolved;
    try {
        apply_preset_file(resolved, resolve_preset(preset));
    } catch (const std::exception& e) {
        throw py::value_error(e.what());
    }
    const auto apply = [&](const py::handle& key, const py::handle& value) {
        const P id = param_named(py::str(key).cast<std::string>());
        resolved.assign(id, param_value(id, value));
    };
    if (!settings.is_none()) {
        if (!py::isinstance<py::dict>(settings))
            throw py::type_error("settings: expected a dict of key: value");
        for (const auto& [key, value] : settings.cast<py::dict>()) apply(key, value);
    }
    for (const auto& [key, value] : params) apply(key, value);
    return resolved;
}

std::optional<ActuatorProfile> resolve_actuator_for(const py::object& name_or_path,
                                                    const Settings& settings) {
    if (name_or_path.is_none()) return std::nullopt;
    ActuatorProfile actuator;
    try {
        actuator = load_actuator(resolve_actuator(py::str(name_or_path).cast<std::string>()));
    } catch (const std::exception& e) {
        throw py::value_error(e.what());
    }
    const py::object warn = py::module_::import("warnings").attr("warn");
    for (const auto& warning : actuator_warnings(actuator, settings))
        warn(warning, py::arg("stacklevel") = 2);
    return actuator;
}

std::vector<ActuatorOutput> resolve_outputs(const py::object& layout, const py::object& actuator,
                                            int actuators, const Settings& settings) {
    if (layout.is_none()) {
        if (actuators < 1 || actuators > Engine::kMaxActuators)
            throw py::value_error(fmt::format("actuators = {} is out of range: allowed 1 to {}",
                                              actuators, Engine::kMaxActuators));
        return std::vector<ActuatorOutput>(
            static_cast<size_t>(actuators),
            ActuatorOutput{.profile = resolve_actuator_for(actuator, settings)});
    }
    if (!actuator.is_none() || actuators != 1)
        throw py::value_error(
            "layout= gives the outputs and their actuators: leave out "
            "actuator= and actuators=");
    try {
        return load_layout(resolve_layout(py::str(layout).cast<std::string>()))
            .actuator_outputs([&](const std::string& name) {
                return *resolve_actuator_for(py::str(name), settings);
            });
    } catch (const std::exception& e) {
        throw py::value_error(e.what());
    }
}

}  // namespace tactus::python
