// Where named data files (presets, actuator profiles) are looked up: the directories of a
// colon-separated environment variable, then the installed/source folder.
#pragma once

#include <filesystem>
#include <vector>

namespace tactus {

std::vector<std::filesystem::path> search_path(const char* environment_variable,
                                               const std::filesystem::path& fallback);

}  // namespace tactus
