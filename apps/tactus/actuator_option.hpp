// --actuator NAME|FILE.toml, shared by the commands that drive or meter an actuator.
#pragma once

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <string>

#include "global_options.hpp"
#include "tactus/actuator/warnings.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/render_info.hpp"

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

// For a command that reads a vibration file (`what`: "metered", "simulated"): the profile named,
// else the one the file says it was rendered for (said on stderr), else the default.
inline ActuatorProfile actuator_of_vibration(const std::string& named, const std::string& input,
                                             const std::string& what) {
    std::string name = named;
    if (name.empty()) {
        name = RenderInfo::from_comment(AudioReader(input).comment()).actuator;
        if (!name.empty())
            note(fmt::format("{}: rendered for {}: {} through it", input, name, what));
        else
            name = kDefaultActuator;
    }
    return load_actuator(resolve_actuator(name));
}

}  // namespace tactus::cli
