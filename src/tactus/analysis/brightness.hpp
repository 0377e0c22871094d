// Brightness: spectral centroid on a logarithmic frequency axis, in Hz: the magnitude-weighted
// geometric mean frequency exp(sum |X_k| ln f_k / sum |X_k|), DC excluded. The paper maps
// brightness~ to vibrotactile pitch "so that the kick and snare drums would be represented by
// separate pitches", on a logarithmic scale (§6). On a log axis a kick's beater click, spread
// thinly over many high bins, does not outweigh its body. Only bins up to max_hz count
// (brightness.max_hz, 1.5 kHz in tfd): a drum's body lies below (a kick's under 150 Hz, a
// snare's shell at 150-400 Hz), and above it a beater's click and a snare's wires are both
// noise, which made a clicky kick as bright as a snare (Sonic Pi's bd_zome has 46 % of its first
// 10 ms above 1 kHz, sn_zome 28 %; felt snare/kick 0.98 with the whole band, 2.19 with 1.5 kHz;
// eval/results.md). A sine below max_hz reads its own frequency; silence reads 0.
#pragma once

#include <span>
#include <vector>

namespace tactus {

class Brightness {
  public:
    void prepare(int bins, double bin_hz, double max_hz);  // may allocate (ln k per bin)
    void set_max_hz(double max_hz) noexcept;               // live (audio thread)
    double centroid_hz(std::span<const float> magnitudes) const noexcept;

  private:
    std::vector<double> log_bin_;  // ln k, k = 1 ... bins - 1
    double bin_hz_ = 1;
    int counted_ = 0;  // bins 1 ... counted_ count
};

}  // namespace tactus
