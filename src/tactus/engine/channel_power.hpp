// The loudness of several input channels as ITU-R BS.1770-4 sums them (eq. 2): each channel
// K-weighted, the squares added. Every channel weighs 1 (the standard's 1.41 for surround
// channels needs a speaker layout the input does not carry). The engine computes this power
// before it downmixes, and the analysis reads its loudness from it (Loudness::process_power):
// a stereo recording with the same signal on both channels reads 3 dB louder than its mono
// mixdown, as it sounds through two speakers.
#pragma once

#include <vector>

#include "tactus/analysis/k_weighting.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class ChannelPower {
  public:
    void prepare(const ProcessSpec& spec);  // spec.channels filters; allocates
    void reset() noexcept;
    int latency() const { return 0; }
    // power[0 ... count): the summed K-weighted power of in[c][offset ...] over the channels,
    // each sample read as the analysis reads it (dsp/sanitize.hpp).
    void process(const float* const* in, int offset, int count, float* power) noexcept;

  private:
    std::vector<KWeighting> channels_;
    std::vector<float> clean_;  // two channels' sanitised input, one block each
};

}  // namespace tactus
