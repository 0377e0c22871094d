// Atomic outputs: write beside the target under a hidden temporary name, then rename over it.
#pragma once

#include <filesystem>

namespace tactus {

// ".NAME.tmp-PID" in the target's directory (same file system, so rename is atomic).
std::filesystem::path temporary_path_for(const std::filesystem::path& target);
// Renames temporary -> target; on failure removes the temporary and throws std::runtime_error.
void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& target);

}  // namespace tactus
