// Settings, presets and actuators as the command line resolves them (--preset, --set,
// --actuator), from Python arguments. Parameters are named by their table key
// ("envelope.decay_ms", in a `settings` dict) or by their Python name, the key with its dots
// as underscores ("envelope_decay_ms", as keyword arguments and Engine attributes).
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "tactus/actuator/profile.hpp"
#include "tactus/engine/output_trim.hpp"
#include "tactus/params/params.hpp"

namespace tactus::python {

// A key or Python name; ValueError "unknown key 'x' (did you mean 'y'?)".
P param_named(const std::string& name);
// The value a Python object stands for: a number, or a choice's name ("log", "on").
double param_value(P id, const pybind11::handle& value);

// The preset, then `settings` (a dict by key or Python name, may be None), then `params`
// (keyword arguments by Python name). ValueError with the library's one-line message.
Settings resolve_settings(const std::string& preset, const pybind11::object& settings,
                          const pybind11::kwargs& params);
// None: no actuator. Its warnings (what the settings ask that it cannot do) as Python
// warnings, one each, as the command line prints them.
std::optional<ActuatorProfile> resolve_actuator_for(const pybind11::object& name_or_path,
                                                    const Settings& settings);
// The engine's outputs: `layout`'s (a name or a .toml path: io/layout_file.hpp; each output with
// its route, overlay, trim, delay and profile), else `actuators` outputs through `actuator`.
// ValueError naming what is wrong (a layout given with an actuator or actuators too).
std::vector<ActuatorOutput> resolve_outputs(const pybind11::object& layout,
                                            const pybind11::object& actuator, int actuators,
                                            const Settings& settings);

}  // namespace tactus::python
