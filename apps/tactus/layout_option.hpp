// --layout NAME|FILE.toml, shared by the commands that render or drive several actuators: the
// outputs, their channels and what each plays (io/layout_file.hpp).
#pragma once

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <map>
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

// The engine's outputs for `layout`, each with its profile loaded (one-line error naming the
// layout and the output).
inline std::vector<ActuatorOutput> layout_outputs(const Layout& layout, const Settings& settings) {
    std::vector<ActuatorOutput> outputs = layout.actuator_outputs();
    std::map<std::string, ActuatorProfile> loaded;  // each profile once (and its warnings)
    for (size_t k = 0; k < outputs.size(); ++k) {
        const LayoutOutput& o = layout.outputs[k];
        if (o.actuator.empty()) continue;
        try {
            if (!loaded.contains(o.actuator))
                loaded.emplace(o.actuator, load_actuator_for(o.actuator, settings));
            outputs[k].profile = loaded.at(o.actuator);
        } catch (const std::exception& e) {
            throw std::runtime_error(
                fmt::format("layout {}: output {}: {}", layout.name, o.name, e.what()));
        }
    }
    return outputs;
}

}  // namespace tactus::cli
