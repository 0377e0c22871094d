#include "tactus/io/temporary_path.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace tactus {
namespace {

// Fixed slots, so the signal handler reads plain memory: a slot's path is written before its
// `used` flag is published and cleared only after the flag is withdrawn.
struct Slot {
    std::atomic<bool> claimed{false};  // owned by a tracker (possibly still filling `path`)
    std::atomic<bool> used{false};     // `path` is complete and may be unlinked
    char path[PATH_MAX]{};
};
Slot g_slots[kMaxTrackedTemporaries];

void unlink_tracked_and_reraise(int signal_number) {
    for (Slot& slot : g_slots)
        if (slot.used.load(std::memory_order_acquire)) unlink(slot.path);
    ::signal(signal_number, SIG_DFL);
    ::raise(signal_number);
}

void untrack(const std::filesystem::path& temporary) noexcept {
    for (Slot& slot : g_slots)
        if (slot.used.load(std::memory_order_acquire) && temporary.native() == slot.path) {
            slot.used.store(false, std::memory_order_release);
            slot.claimed.store(false, std::memory_order_release);
            return;
        }
}

// The file writing `target` replaces: a symlink's final target (the link stays), else target.
std::filesystem::path replaced_file(const std::filesystem::path& target) {
    std::error_code error;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(target, error))) return target;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(target, error);
    return error ? target : resolved;
}

// Copies the bytes of `from` into `target` (stdout for "-"), opened for writing as it is.
bool copy_into(const std::filesystem::path& from, const std::filesystem::path& target) {
    const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) return false;
    const int out = target == "-" ? STDOUT_FILENO : ::open(target.c_str(), O_WRONLY | O_CLOEXEC);
    bool ok = out >= 0;
    char buffer[1 << 16];
    for (ssize_t n; ok && (n = ::read(in, buffer, sizeof buffer)) != 0;) {
        if (n < 0) {
            ok = errno == EINTR;
            continue;
        }
        for (ssize_t done = 0; ok && done < n;) {
            const ssize_t w = ::write(out, buffer + done, static_cast<size_t>(n - done));
            if (w < 0 && errno != EINTR) ok = false;
            if (w > 0) done += w;
        }
    }
    const int reason = errno;
    ::close(in);
    if (out >= 0 && out != STDOUT_FILENO) ::close(out);
    errno = reason;
    return ok;
}

}  // namespace

bool written_in_place(const std::filesystem::path& target) {
    if (target == "-") return true;
    std::error_code error;
    const auto status = std::filesystem::status(target, error);  // follows symlinks
    return !error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
           !std::filesystem::is_directory(status);
}

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
    if (written_in_place(target)) {
        static std::atomic<int> count{0};
        return std::filesystem::temp_directory_path() /
               fmt::format(".tactus-out.tmp-{}-{}", getpid(), count++);
    }
    const std::filesystem::path file = replaced_file(target);
    return file.parent_path() / fmt::format(".{}.tmp-{}", file.filename().string(), getpid());
}

void track_temporary(const std::filesystem::path& temporary) {
    const std::string& text = temporary.native();
    if (text.size() >= PATH_MAX)
        throw std::runtime_error(fmt::format("{}: path too long", temporary.string()));
    for (Slot& slot : g_slots) {
        bool expected = false;
        if (!slot.claimed.compare_exchange_strong(expected, true, std::memory_order_acq_rel))
            continue;
        std::memcpy(slot.path, text.c_str(), text.size() + 1);
        slot.used.store(true, std::memory_order_release);
        return;
    }
    throw std::runtime_error(
        fmt::format("more than {} outputs open at once", kMaxTrackedTemporaries));
}

void commit_temporary(const std::filesystem::path& temporary, const std::filesystem::path& target) {
    if (written_in_place(target)) {
        const bool copied = copy_into(temporary, target);
        const int reason = errno;
        discard_temporary(temporary);
        if (!copied)
            throw std::runtime_error(
                fmt::format("{}: cannot write: {}", target.string(), std::strerror(reason)));
        return;
    }
    std::error_code error;
    std::filesystem::rename(temporary, replaced_file(target), error);
    if (error) {
        discard_temporary(temporary);
        throw std::runtime_error(
            fmt::format("{}: cannot write: {}", target.string(), error.message()));
    }
    untrack(temporary);
}

void discard_temporary(const std::filesystem::path& temporary) noexcept {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    untrack(temporary);
}

void remove_temporaries_on_signals() {
    struct sigaction action {};
    action.sa_handler = unlink_tracked_and_reraise;
    sigemptyset(&action.sa_mask);
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP})
        sigaction(signal_number, &action, nullptr);
}

}  // namespace tactus
