// What the analysis reads of an input sample: non-finite and denormal samples as 0, levels
// beyond +-kMaxInputLevel clipped.
#pragma once

#include <cmath>
#include <limits>

namespace tactus {

// +60 dB over full scale: only corrupt input gets there, and it would overflow the float sums
// of squares of the spectra.
inline constexpr float kMaxInputLevel = 1000.0f;

// Comparisons, not std::isnormal: a loop of them vectorises.
inline float sanitized(float x) noexcept {
    constexpr float max_level = kMaxInputLevel;
    const float magnitude = std::fabs(x);
    return magnitude >= std::numeric_limits<float>::min() && magnitude <= max_level ? x
           : magnitude > max_level && magnitude <= std::numeric_limits<float>::max()
               ? std::copysign(max_level, x)
               : 0.0f;
}

}  // namespace tactus
