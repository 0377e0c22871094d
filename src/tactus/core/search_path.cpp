#include "tactus/core/search_path.hpp"

#include <cstdlib>
#include <string_view>

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

}  // namespace tactus
