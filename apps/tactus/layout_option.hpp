// --layout NAME|FILE.toml, shared by the commands that render or drive several actuators: the
// outputs, their channels and what each plays (io/layout_file.hpp).
#pragma once

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "actuator_option.hpp"
#include "tactus/io/layout_file.hpp"

namespace tactus::cli {

inline CLI::Option* add_layout_option(CLI::App& command, std::string& layout) {
    return command.add_option(
        "--layout", layout,
        "the actuator outputs and what each plays: a name in layouts/ (controller, wrists, seat, "
        "column-4) or FILE.toml");
}

// The engine's outputs for `layout`, each profile loaded as --actuator loads one (its warnings on
// stderr, once).
inline std::vector<ActuatorOutput> layout_outputs(const Layout& layout, const Settings& settings) {
    return layout.actuator_outputs(
        [&](const std::string& name) { return load_actuator_for(name, settings); });
}

}  // namespace tactus::cli
