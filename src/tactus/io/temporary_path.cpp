#include "tactus/io/temporary_path.hpp"

#include <fmt/format.h>
#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
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

}  // namespace

std::filesystem::path temporary_path_for(const std::filesystem::path& target) {
    const auto name = fmt::format(".{}.tmp-{}", target.filename().string(), getpid());
    return target.parent_path() / name;
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
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
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
