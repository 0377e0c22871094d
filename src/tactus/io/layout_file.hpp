// Layouts: the actuator outputs of a device or a vibration file and what each plays, in TOML
// files found by name as presets and actuator profiles are (layouts/*.toml, io/search_path.hpp):
//   description = "a game controller: ..."
//   channels = 4               # the device's or the file's channels (default: as many as used)
//   sound = [1, 2]             # channels carrying the sound itself, from 1 (default: none)
//   [[output]]
//   name = "left"              # names the output in exports, the meter and the report
//   channel = 3                # its channel, from 1 (default: the first one not yet taken)
//   route = "channel:1"        # what it plays (engine/route.hpp; default "all")
//   actuator = "voice-coil"    # its profile, a name or a file (default: none)
//   gain_db = 0                # trim after the limiter, -60 to 0
//   delay_ms = 0               # alignment, 0 to 1000 ms
//   [output.set]               # its own values of the mapping's parameters, as a preset's
//   mapping.frequency.out_max = 200
// Errors are one line, "FILE:LINE:COL: key: problem".
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "tactus/engine/output_trim.hpp"

namespace tactus {

struct LayoutOutput {
    std::string name;
    int channel = 0;        // counted from 0
    std::string actuator;   // a profile's name or path; empty: none
    ActuatorOutput output;  // route, overlay, trim and delay; the caller loads the profile
};

struct Layout {
    std::string name, description;
    int channels = 0;                 // outputs and sound channels all lie below it
    std::vector<int> sound_channels;  // counted from 0
    std::vector<LayoutOutput> outputs;

    // Loads the profile an output names (a name or a path), as the front end loads one (its
    // warnings said its way); throws on a bad one.
    using ProfileLoader = std::function<ActuatorProfile(const std::string& name_or_path)>;
    // The engine's outputs, in the layout's order, each named profile loaded once however many
    // outputs name it; throws std::runtime_error "layout NAME: output OUTPUT: problem".
    std::vector<ActuatorOutput> actuator_outputs(const ProfileLoader& load_profile) const;
};

// Directories searched for layouts by name ($TACTUS_LAYOUT_PATH, then as io/search_path.hpp).
std::vector<std::filesystem::path> layout_search_path();
// A name ("controller") or a path to a .toml file.
std::filesystem::path resolve_layout(std::string_view name_or_path);
// Reads and validates a layout; throws std::runtime_error "FILE:LINE:COL: key: problem".
Layout load_layout(const std::filesystem::path& path);
Layout parse_layout(std::string_view toml_text, std::string_view origin);

}  // namespace tactus
