#include "tactus/io/temporary_path.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <stdexcept>

namespace tactus {

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
    const auto name = fmt::format(".{}.tmp-{}", target.filename().string(), getpid());
    return target.parent_path() / name;
}

void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& target) {
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error(
            fmt::format("{}: cannot write: {}", target.string(), error.message()));
    }
}

}  // namespace tactus
