// Brightness: spectral centroid on a logarithmic frequency axis, in Hz: the magnitude-weighted
// geometric mean frequency exp(sum |X_k| ln f_k / sum |X_k|), DC excluded. The paper maps
// brightness~ to vibrotactile pitch "so that the kick and snare drums would be represented by
// separate pitches", on a logarithmic scale (§6). On a log axis a kick's beater click, spread
// thinly over many high bins, does not outweigh its body. A sine reads its own frequency;
// silence reads 0.
#pragma once

#include <span>

namespace tactus {

double spectral_centroid_hz(std::span<const float> magnitudes, double bin_hz) noexcept;

}  // namespace tactus
