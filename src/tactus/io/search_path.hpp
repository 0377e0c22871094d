// Where named data files (presets, actuator profiles) are looked up: the directories of a
// colon-separated environment variable, then the installed/source folder. A name is found as
// NAME.toml in the first directory that has it; a path (with a folder or .toml) is used as is.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tactus {

std::vector<std::filesystem::path> search_path(const char* environment_variable,
                                               const std::filesystem::path& fallback);

// The NAME.toml files in `dirs` by NAME, sorted; a name in an earlier directory hides the same
// name in later ones.
std::map<std::string, std::filesystem::path> toml_files(
    const std::vector<std::filesystem::path>& dirs);

// Throws std::runtime_error "no KIND named 'x' (known: a, b)" or "KIND file 'x' not found".
std::filesystem::path resolve_toml(std::string_view name_or_path,
                                   const std::vector<std::filesystem::path>& dirs,
                                   std::string_view kind);

}  // namespace tactus
