// --actuator NAME|FILE.toml, shared by the commands that drive or meter an actuator.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "global_options.hpp"
#include "tactus/actuator/warnings.hpp"
#include "tactus/io/actuator_file.hpp"

namespace tactus::cli {

inline void add_actuator_option(CLI::App& command, std::string& actuator, const std::string& help) {
    command.add_option("--actuator,-a", actuator, help);
}

// Loads the profile (one-line error if it is missing or invalid) and prints on stderr, one
// line each, what the settings ask of it that it cannot do (unless --quiet).
inline ActuatorProfile load_actuator_for(const std::string& name_or_path,
                                         const Settings& settings) {
    ActuatorProfile actuator = load_actuator(resolve_actuator(name_or_path));
    for (const auto& warning : actuator_warnings(actuator, settings))
        note("tactus: warning: " + warning);
    return actuator;
}

}  // namespace tactus::cli
