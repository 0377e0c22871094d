// The ITU-R BS.1770-4 K-weighting (a high shelf and the RLB high-pass), coefficients
// re-derived for any sample rate as in libebur128 (ebur128.c): the loudness of one channel
// (Loudness) and of several, summed as the standard sums them (ChannelPower).
#pragma once

#include "tactus/dsp/biquad.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class KWeighting {
  public:
    void prepare(const ProcessSpec& spec);
    void reset() noexcept {
        shelf_.reset();
        highpass_.reset();
    }
    int latency() const { return 0; }
    // Adds the square of each K-weighted sample to power[i].
    void add_power(const float* samples, float* power, int count) noexcept;
    // One sample, K-weighted.
    double process(double x) noexcept { return highpass_.process(shelf_.process(x)); }

  private:
    Biquad shelf_, highpass_;
};

}  // namespace tactus
