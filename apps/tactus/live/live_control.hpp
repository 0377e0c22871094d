// The control side of `tactus live`: the one door through which the OSC server and the preset
// watcher (each on its own thread) change the running engine. It keeps no settings of its own:
// the engine's are the running ones (Engine::settings_snapshot, thread-safe), a parameter is
// set there in one step, and a preset (with the command line's --set on top) is handed to
// Engine::set whole, which applies what differs (live ones glide, structural ones are swapped in
// with a crossfade: engine.hpp). When the engine's change queue is full
// (Engine::kChangeCapacity) it waits for the audio thread to take some.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "osc_address_space.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/layout_file.hpp"

namespace tactus::live {

class LiveControl {
  public:
    // `assignments`: the command line's --set, kept on top of any preset loaded later;
    // `load_profile`: how a layout's actuator profiles are loaded (the command line's says
    // their warnings); by default, loaded and checked only.
    LiveControl(Engine& engine, std::vector<std::string> assignments,
                Layout::ProfileLoader load_profile = {});

    // Control threads. Each throws (std::invalid_argument, std::runtime_error) with one line
    // and then has changed nothing (a preset: nothing from the parameter that failed on).
    void set(P id, double value);
    // The preset file (a name or a path) with the --set assignments on top, applied as the
    // parameters that differ from the running ones.
    void load_preset(const std::string& name_or_path);
    void load_preset_file(const std::filesystem::path& path);
    // A layout's routes, overlays, profiles and trims (Engine::set_outputs; its channels and
    // delays are the device's, set when it opened: a layout with other delays is refused); it
    // must have as many outputs as there are actuators.
    void load_layout(const std::string& name_or_path);
    void run(const OscCommand& command);
    // Any control thread: the engine's settings, whole.
    Settings settings() const { return engine_.settings(); }
    int actuators() const { return engine_.actuators(); }

  private:
    template <typename F>
    void retry_while_full(F&& change);

    Engine& engine_;
    const std::vector<std::string> assignments_;
    const Layout::ProfileLoader load_profile_;
};

}  // namespace tactus::live
