// Noisiness: spectral flatness across Bark critical bands, 0 (tonal) ... 1 (noise).
// Power is averaged within each critical band (Zwicker & Terhardt band edges), then flatness is
// the geometric over the arithmetic mean of those band power densities: white noise gives ~1,
// a sine ~0. After Jehan's noisiness~ (the paper's §6 timbre control).
#pragma once

#include <span>
#include <vector>

namespace tactus {

class Noisiness {
  public:
    void prepare(int bins, double bin_hz);  // may allocate
    double compute(std::span<const float> powers) const noexcept;

  private:
    struct Band {
        int first_bin, end_bin;
    };
    std::vector<Band> bands_;
};

}  // namespace tactus
