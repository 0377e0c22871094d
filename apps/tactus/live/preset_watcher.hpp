// Reloads the running preset when its file changes (inotify on its folder, so an editor's
// write-and-rename is seen too). The new settings go through LiveControl, the engine's live path:
// live parameters glide, structural ones crossfade, nothing allocates on the audio thread. A file
// with an error keeps the running settings and says why, in one line.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>

#include "live_control.hpp"

namespace tactus::live {

class PresetWatcher {
  public:
    // `report`: one line per reload or refusal. Throws std::runtime_error if the folder cannot
    // be watched.
    PresetWatcher(const std::filesystem::path& preset, LiveControl& control,
                  std::function<void(const std::string&)> report);
    ~PresetWatcher();
    PresetWatcher(const PresetWatcher&) = delete;
    PresetWatcher& operator=(const PresetWatcher&) = delete;

    // Any thread: reloads done (successful or not), for tests.
    int reloads() const { return reloads_.load(); }

  private:
    void run();
    std::filesystem::path preset_;
    LiveControl& control_;
    std::function<void(const std::string&)> report_;
    int inotify_ = -1;
    std::atomic<bool> stop_{false};
    std::atomic<int> reloads_{0};
    std::thread thread_;
};

}  // namespace tactus::live
