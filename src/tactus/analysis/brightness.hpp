// Brightness: spectral centroid on a logarithmic frequency axis, in Hz: the magnitude-weighted
// geometric mean frequency exp(sum |X_k| ln f_k / sum |X_k|), DC excluded. The paper maps
// brightness~ to vibrotactile pitch "so that the kick and snare drums would be represented by
// separate pitches", on a logarithmic scale (§6). On a log axis a kick's beater click, spread
// thinly over many high bins, does not outweigh its body. A sine reads its own frequency;
// silence reads 0.
#pragma once

#include <span>
#include <vector>

namespace tactus {

class Brightness {
  public:
    void prepare(int bins, double bin_hz);  // may allocate (ln k per bin)
    double centroid_hz(std::span<const float> magnitudes) const noexcept;

  private:
    std::vector<double> log_bin_;  // ln k, k = 1 ... bins - 1
    double bin_hz_ = 1;
};

}  // namespace tactus
