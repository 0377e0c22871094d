// The commands that need libraries the others never load (audio devices: RtAudio, JACK, ALSA,
// liblo; the studio's web server: cpp-httplib, OpenSSL, brotli) live in helper programs of their
// own, which `tactus` runs in its place when one of them is chosen (helper_programs.hpp): every
// other command starts without loading those libraries. Their names and one-line descriptions,
// written once for the helper that runs them and for `tactus --help`.
#pragma once

namespace tactus::cli {

struct HelperCommand {
    const char* name;
    const char* description;
    const char* program;  // in the helpers' folder, beside the others
};

inline constexpr HelperCommand kLiveCommand{
    "live", "sound and vibration on audio devices, from an instrument's input or a player",
    "tactus-live"};
inline constexpr HelperCommand kDevicesCommand{
    "devices", "list the audio backends and devices `tactus live` can use", "tactus-live"};
inline constexpr HelperCommand kCalibrateCommand{
    "calibrate", "measure an actuator with a swept sine and a sensor; write its profile",
    "tactus-live"};
inline constexpr HelperCommand kStudioCommand{
    "studio", "tune a sound's vibration in the browser: plots, controls, players, exports",
    "tactus-studio"};

}  // namespace tactus::cli
