// What the analysis reads of an input sample: non-finite and denormal samples as 0, levels
// beyond +-max_level clipped (only corrupt input gets there).
#pragma once

#include <cmath>
#include <limits>

namespace tactus {

// Comparisons, not std::isnormal: a loop of them vectorises.
inline float sanitized(float x, float max_level) noexcept {
    const float magnitude = std::fabs(x);
    return magnitude >= std::numeric_limits<float>::min() && magnitude <= max_level ? x
           : magnitude > max_level && magnitude <= std::numeric_limits<float>::max()
               ? std::copysign(max_level, x)
               : 0.0f;
}

}  // namespace tactus
