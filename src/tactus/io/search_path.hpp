// Where named data files (presets, actuator profiles, layouts) are looked up, in order: the
// directories of a colon-separated environment variable ($TACTUS_PRESET_PATH,
// $TACTUS_ACTUATOR_PATH, $TACTUS_LAYOUT_PATH), the user's data directory
// ($XDG_DATA_HOME/tactus/FOLDER, by default ~/.local/share/tactus/FOLDER), and the data
// installed with the code: FOLDER in the first share/tactus above a program
// (PROGRAM_DIR/../share/tactus for bin/tactus, ../../share/tactus for the command line's helpers
// in libexec/tactus; the build tree has the same layout); for a module another program loads (the
// Pd external, the Python module, the Vamp plugin), MODULE_DIR/FOLDER when the module's folder is a
// bundle that holds its data, else FOLDER in the first share/tactus above the module. No path is
// compiled in. A name is found as NAME.toml in the first directory that has it; a path (with a
// folder or .toml) is used as is.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tactus {

// folder: "presets", "actuators" or "layouts".
std::vector<std::filesystem::path> search_path(const char* environment_variable,
                                               std::string_view folder);
// The first PROGRAM_DIR/../.../share/tactus that exists (else PROGRAM_DIR/../share/tactus), or for
// a loaded module its bundle's folder or the first MODULE_DIR/../.../share/tactus that exists;
// empty when the running program's path is unknown.
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
