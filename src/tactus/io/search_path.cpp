#include "tactus/io/search_path.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <link.h>

#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>

#include "tactus/core/nearest.hpp"
#include "tactus/core/printable.hpp"

namespace tactus {
namespace {

// FROM/share/tactus, or the first such folder above FROM, if one exists.
std::optional<std::filesystem::path> share_above(std::filesystem::path from) {
    std::error_code missing;
    for (; from != from.root_path(); from = from.parent_path())
        if (std::filesystem::is_directory(from / "share" / "tactus", missing))
            return from / "share" / "tactus";
    return std::nullopt;
}

}  // namespace

std::filesystem::path installed_data_dir() {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path program = fs::read_symlink("/proc/self/exe", error);
    // Linked into a module another program loads (a Pd external, a Python module, a plugin):
    // the module's own folder when it holds the data (a bundle: tactus~/presets), else the first
    // folder above the module that holds share/tactus (an installed prefix, the build tree).
    Dl_info module{};
    link_map* module_map = nullptr;
    link_map* program_map = nullptr;
    if (void* self = dlopen(nullptr, RTLD_LAZY)) {
        dlinfo(self, RTLD_DI_LINKMAP, &program_map);
        dlclose(self);
    }
    if (dladdr1(reinterpret_cast<const void*>(&installed_data_dir), &module,
                reinterpret_cast<void**>(&module_map), RTLD_DL_LINKMAP) &&
        module_map && module_map != program_map && module.dli_fname && *module.dli_fname) {
        std::error_code unreadable;
        const fs::path file = fs::weakly_canonical(module.dli_fname, unreadable);
        std::error_code missing;
        if (!unreadable) {
            if (fs::is_directory(file.parent_path() / "presets", missing) ||
                fs::is_directory(file.parent_path() / "actuators", missing))
                return file.parent_path();
            if (auto data = share_above(file.parent_path())) return *data;
        }
    }
    if (program.empty()) return {};
    // A program: the first folder above it that holds share/tactus (bin/tactus, and the command
    // line's helpers in libexec/tactus), else PROGRAM_DIR/../share/tactus.
    return share_above(program.parent_path().parent_path())
        .value_or(program.parent_path().parent_path() / "share" / "tactus");
}

std::vector<std::filesystem::path> search_path(const char* environment_variable,
                                               std::string_view folder) {
    std::vector<std::filesystem::path> dirs;
    if (const char* env = std::getenv(environment_variable)) {
        std::string_view rest = env;
        while (!rest.empty()) {
            const size_t colon = rest.find(':');
            if (colon != 0) dirs.emplace_back(rest.substr(0, colon));
            if (colon == std::string_view::npos) break;
            rest.remove_prefix(colon + 1);
        }
    }
    if (const char* data_home = std::getenv("XDG_DATA_HOME"); data_home && *data_home)
        dirs.push_back(std::filesystem::path(data_home) / "tactus" / folder);
    else if (const char* home = std::getenv("HOME"); home && *home)
        dirs.push_back(std::filesystem::path(home) / ".local" / "share" / "tactus" / folder);
    if (const auto installed = installed_data_dir(); !installed.empty())
        dirs.push_back(installed / folder);
    return dirs;
}

std::map<std::string, std::filesystem::path> toml_files(
    const std::vector<std::filesystem::path>& dirs) {
    std::map<std::string, std::filesystem::path> files;
    for (const auto& dir : dirs) {
        std::error_code ec;
        for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
            if (entry.path().extension() == ".toml")
                files.emplace(entry.path().stem().string(), entry.path());  // keeps the first
    }
    return files;
}

std::filesystem::path resolve_toml(std::string_view name_or_path,
                                   const std::vector<std::filesystem::path>& dirs,
                                   std::string_view kind) {
    namespace fs = std::filesystem;
    fs::path given(name_or_path);
    std::error_code error;
    if (given.extension() == ".toml" || given.has_parent_path()) {
        if (!fs::is_regular_file(given, error))
            throw std::runtime_error(
                fmt::format("{} file '{}' {}", kind, printable(name_or_path),
                            error && error != std::errc::no_such_file_or_directory ? error.message()
                                                                                   : "not found"));
        return given;
    }
    // A directory the user cannot read (another user's home) is passed over like a missing one.
    for (const auto& dir : dirs)
        if (fs::is_regular_file(dir / (given.string() + ".toml"), error))
            return dir / (given.string() + ".toml");
    // Named as people type it: "LRA-175", "four_channel".
    const auto files = toml_files(dirs);
    for (const auto& [name, path] : files)
        if (folded_name(name) == folded_name(name_or_path)) return path;
    std::string known;
    std::vector<std::string> names;
    for (const auto& [name, path] : files) {
        known += (known.empty() ? "" : ", ") + name;
        names.push_back(name);
    }
    const std::string nearest = nearest_name(name_or_path, names);
    throw std::runtime_error(
        fmt::format("no {} named '{}' ({}known: {})", kind, printable(name_or_path),
                    nearest.empty() ? "" : "did you mean '" + nearest + "'? ", known));
}

}  // namespace tactus
