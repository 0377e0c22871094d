#include "tactus/io/search_path.hpp"

#include <fmt/format.h>

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "tactus/core/printable.hpp"

namespace tactus {

std::filesystem::path installed_data_dir() {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    // The object holding this code: the program itself (its link map has no name), or a shared
    // object loaded into another program (a Pd external, a plugin, a Python module).
    Dl_info info{};
    link_map* object = nullptr;
    if (dladdr1(reinterpret_cast<const void*>(&installed_data_dir), &info,
                reinterpret_cast<void**>(&object), RTLD_DL_LINKMAP) != 0 &&
        object && object->l_name && object->l_name[0] != '\0') {
        const std::filesystem::path module = std::filesystem::weakly_canonical(object->l_name, error);
        if (!error) return module.parent_path();
    }
    if (program.empty()) return {};
    return program.parent_path().parent_path() / "share" / "tactus";
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
    const fs::path given(name_or_path);
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
    std::string known;
    for (const auto& [name, path] : toml_files(dirs)) known += (known.empty() ? "" : ", ") + name;
    throw std::runtime_error(
        fmt::format("no {} named '{}' (known: {})", kind, printable(name_or_path), known));
}

}  // namespace tactus
