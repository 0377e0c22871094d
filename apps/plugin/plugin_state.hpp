// The plugin's saved state is the engine's state: every parameter as preset text
// (preset_text(), src/tactus/io/preset.hpp), so a session reads like a preset and loads back
// bit for bit. A state coming back from a host is validated as a preset is; anything that is
// not a valid preset (corrupt, truncated, another plugin's, a newer format) gives the table's
// defaults and a one-line message, never an exception.
#pragma once

#include <string>
#include <string_view>

#include "tactus/params/params.hpp"

namespace tactus::plugin {

inline constexpr const char* kStateKey = "state";

struct RestoredState {
    Settings settings;  // the state's, or the defaults if it was refused
    std::string error;  // empty when the state was taken; else one line saying why not
};

std::string state_text(const Settings& settings);
RestoredState restore_state(std::string_view text) noexcept;

}  // namespace tactus::plugin
