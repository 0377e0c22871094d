// The control side of `tactus live`: the one door through which the OSC server and the preset
// watcher (each on its own thread) change the running engine. It keeps the settings it applied,
// turns a preset into the parameters that differ from them, and hands each to Engine::set (live
// ones glide, structural ones are swapped in with a crossfade: engine.hpp). When the engine's
// change queue is full (Engine::kChangeCapacity) it waits for the audio thread to take some.
#pragma once

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "osc_address_space.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus::live {

class LiveControl {
  public:
    // `running`: the settings the engine was made with; `assignments`: the command line's --set,
    // kept on top of any preset loaded later.
    LiveControl(Engine& engine, Settings running, std::vector<std::string> assignments);

    // Control threads. Each throws (std::invalid_argument, std::runtime_error) with one line
    // and then has changed nothing (a preset: nothing from the parameter that failed on).
    void set(P id, double value);
    // The preset file (a name or a path) with the --set assignments on top, applied as the
    // parameters that differ from the running ones.
    void load_preset(const std::string& name_or_path);
    void load_preset_file(const std::filesystem::path& path);
    void run(const OscCommand& command);
    Settings settings() const;
    int actuators() const { return engine_.actuators(); }

  private:
    template <typename F>
    void retry_while_full(F&& change);
    void apply(const Settings& next);

    Engine& engine_;
    mutable std::mutex mutex_;  // control threads among themselves
    Settings running_;
    std::vector<std::string> assignments_;
};

}  // namespace tactus::live
