// Actuator profiles read from TOML files (actuators/*.toml; the format: actuator/profile.hpp),
// found by name on a search path.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "tactus/actuator/profile.hpp"

namespace tactus {

// Directories searched for profiles by name (io/search_path.hpp).
std::vector<std::filesystem::path> actuator_search_path();
// A name ("voice-coil") or a path to a .toml file.
std::filesystem::path resolve_actuator(std::string_view name_or_path);
// Reads and validates a profile; throws std::runtime_error "FILE:LINE:COL: key: problem".
ActuatorProfile load_actuator(const std::filesystem::path& path);
ActuatorProfile parse_actuator(std::string_view toml_text, std::string_view origin);
// Every field of `profile` as a profile file (`comment` atop it, each line prefixed "# "; reals
// in the shortest form that reads back as the same double): parse_actuator() of it gives the
// profile back.
std::string actuator_text(const ActuatorProfile& profile, std::string_view comment);

}  // namespace tactus
