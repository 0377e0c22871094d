// Atomic outputs: write beside the target under a hidden temporary name, then rename over it.
// Temporaries are tracked so that SIGINT, SIGTERM and SIGHUP remove them before the process
// dies; SIGKILL cannot be caught, and then only the hidden temporary is left, never a partial
// target.
#pragma once

#include <filesystem>

namespace tactus {

// ".NAME.tmp-PID" in the directory of the file the target names (same file system, so rename
// is atomic): beside a symlink's final target, so the link stays and what it points to is
// replaced. For a target written in place, a temporary in the system's temporary directory.
std::filesystem::path temporary_path_for(const std::filesystem::path& target);

// Outputs that are written into, never replaced: "-" (stdout), devices, pipes and sockets
// (also through a symlink such as /dev/stdout).
bool written_in_place(const std::filesystem::path& target);

// Tracks `temporary` for removal on a signal (at most kMaxTrackedTemporaries at once; throws
// std::runtime_error beyond). Call before creating the file.
void track_temporary(const std::filesystem::path& temporary);
// Renames temporary -> target (a symlink's final target: the link stays) and stops tracking it;
// a target written in place gets the temporary's bytes copied into it and the temporary is
// removed. On failure removes the temporary and throws std::runtime_error.
void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& target);
// Removes `temporary` (if it exists) and stops tracking it. Never throws.
void discard_temporary(const std::filesystem::path& temporary) noexcept;

// Installs handlers for SIGINT, SIGTERM and SIGHUP that unlink every tracked temporary (only
// async-signal-safe calls), restore the default action and re-raise, so the exit status still
// says which signal ended the process. Idempotent.
void remove_temporaries_on_signals();

inline constexpr int kMaxTrackedTemporaries = 64;

}  // namespace tactus
