// Where named data files (presets, actuator profiles) are looked up, in order: the directories
// of a colon-separated environment variable ($TACTUS_PRESET_PATH, $TACTUS_ACTUATOR_PATH), the
// user's data directory ($XDG_DATA_HOME/tactus/FOLDER, by default ~/.local/share/tactus/FOLDER),
// and the data installed with the code: PROGRAM_DIR/../share/tactus/FOLDER for a program (the
// build tree has the same layout), MODULE_DIR/FOLDER for a shared object loaded into another
// program (a Pd external's folder, a plugin bundle, a Python package hold their data). No path is compiled in. A name is found as NAME.toml in the
// first directory that has it; a path (with a folder or .toml) is used as is.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tactus {

// folder: "presets" or "actuators".
std::vector<std::filesystem::path> search_path(const char* environment_variable,
                                               std::string_view folder);
// PROGRAM_DIR/../share/tactus, or MODULE_DIR for a shared object, or empty when the running
// program's path is unknown.
std::filesystem::path installed_data_dir();

// The NAME.toml files in `dirs` by NAME, sorted; a name in an earlier directory hides the same
// name in later ones.
std::map<std::string, std::filesystem::path> toml_files(
    const std::vector<std::filesystem::path>& dirs);

// Throws std::runtime_error "no KIND named 'x' (known: a, b)" or "KIND file 'x' not found".
std::filesystem::path resolve_toml(std::string_view name_or_path,
                                   const std::vector<std::filesystem::path>& dirs,
                                   std::string_view kind);

}  // namespace tactus
