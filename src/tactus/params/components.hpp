// Which channel components a setting turns on (paper §5: the synthesiser targets the channels of
// touch separately). The P carrier is always on; the NPI flutter when it has a weight; the NPIII
// pressure when it has a weight and the actuator can hold a sustained offset (paper §5.4: the
// TFD's voice coils cannot). Components that are off cost nothing and change nothing.
#pragma once

#include "tactus/params/params.hpp"

namespace tactus {

inline bool flutter_enabled(const Settings& s) {
    return s[P::flutter_weight] > 0.0;
}

inline bool pressure_enabled(const Settings& s) {
    return s[P::pressure_weight] > 0.0 && s[P::actuator_dc] != 0.0;
}

}  // namespace tactus
