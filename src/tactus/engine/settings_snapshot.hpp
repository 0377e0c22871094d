// The engine's settings as one whole copy, with the number of changes that made them
// (Engine::settings_snapshot()). A control thread (an OSC server, a host's main thread, a GUI)
// reads what the engine plays without a reference into what another control thread writes: the
// copy is taken under the engine's control mutex, so it is always one complete Settings that was
// set, never a mix of two. `version` grows by at least one with every change that altered the
// settings (a value the engine already has changes nothing and keeps it), so a reader can tell
// whether anything changed since its last look by comparing two numbers.
#pragma once

#include <cstdint>

#include "tactus/params/params.hpp"

namespace tactus {

struct SettingsSnapshot {
    Settings settings;
    uint64_t version = 0;  // 0: the settings the engine was made with
};

}  // namespace tactus
