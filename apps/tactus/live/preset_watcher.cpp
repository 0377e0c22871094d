#include "preset_watcher.hpp"

#include <fmt/format.h>
#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace tactus::live {
namespace {

constexpr int kPollMs = 50;    // how soon the thread notices it should stop
constexpr int kSettleMs = 30;  // events of one save arrive together: read them all first

}  // namespace

PresetWatcher::PresetWatcher(const std::filesystem::path& preset, LiveControl& control,
                             std::function<void(const std::string&)> report)
    : preset_(std::filesystem::absolute(preset)), control_(control), report_(std::move(report)) {
    inotify_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    const std::filesystem::path folder = preset_.parent_path();
    if (inotify_ < 0 ||
        inotify_add_watch(inotify_, folder.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE) < 0) {
        const std::string why = std::strerror(errno);
        if (inotify_ >= 0) ::close(inotify_);
        throw std::runtime_error(
            fmt::format("{}: cannot watch for changes: {}", folder.string(), why));
    }
    thread_ = std::thread([this] { run(); });
}

PresetWatcher::~PresetWatcher() {
    stop_ = true;
    thread_.join();
    ::close(inotify_);
}

void PresetWatcher::run() {
    alignas(inotify_event) char buffer[4096];
    const std::string name = preset_.filename().string();
    while (!stop_) {
        pollfd waiting{.fd = inotify_, .events = POLLIN, .revents = 0};
        if (::poll(&waiting, 1, kPollMs) <= 0) continue;
        bool changed = false;
        for (int quiet = 0; quiet < 2;) {  // until nothing came during one settle time
            const ssize_t n = ::read(inotify_, buffer, sizeof buffer);
            if (n <= 0) {
                ++quiet;
                ::poll(&waiting, 1, kSettleMs);
                continue;
            }
            quiet = 0;
            for (ssize_t at = 0; at < n;) {
                const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
                if (event->len > 0 && name == event->name && !(event->mask & IN_CREATE))
                    changed = true;
                at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            }
        }
        if (!changed) continue;
        try {
            control_.load_preset_file(preset_);
            report_(fmt::format("{}: reloaded", preset_.string()));
        } catch (const std::exception& e) {
            report_(fmt::format("{}; keeping the running settings", e.what()));
        }
        ++reloads_;
    }
}

}  // namespace tactus::live
