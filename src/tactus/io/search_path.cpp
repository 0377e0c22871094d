#include "tactus/io/search_path.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "tactus/core/printable.hpp"

namespace tactus {

std::vector<std::filesystem::path> search_path(const char* environment_variable,
                                               const std::filesystem::path& fallback) {
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
    dirs.push_back(fallback);
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
    if (given.extension() == ".toml" || given.has_parent_path()) {
        if (!fs::is_regular_file(given))
            throw std::runtime_error(
                fmt::format("{} file '{}' not found", kind, printable(name_or_path)));
        return given;
    }
    for (const auto& dir : dirs)
        if (fs::is_regular_file(dir / (given.string() + ".toml")))
            return dir / (given.string() + ".toml");
    std::string known;
    for (const auto& [name, path] : toml_files(dirs)) known += (known.empty() ? "" : ", ") + name;
    throw std::runtime_error(
        fmt::format("no {} named '{}' (known: {})", kind, printable(name_or_path), known));
}

}  // namespace tactus
