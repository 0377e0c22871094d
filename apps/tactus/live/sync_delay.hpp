// --sync: how long the sound is held back so that it is heard when the vibration it causes is
// felt. PLACEHOLDER
#pragma once

#include "tactus/engine/engine.hpp"

namespace tactus::live {

inline int vibration_delay_samples(const Engine& engine) {
    return engine.latency();
}

}  // namespace tactus::live
