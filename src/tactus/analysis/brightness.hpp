// Brightness: spectral centroid in Hz of the magnitude spectrum (DC excluded). The paper maps
// brightness~ to vibrotactile pitch so kick and snare get separate pitches (§6). Silence reads 0.
#pragma once

#include <span>

namespace tactus {

double spectral_centroid_hz(std::span<const float> magnitudes, double bin_hz) noexcept;

}  // namespace tactus
