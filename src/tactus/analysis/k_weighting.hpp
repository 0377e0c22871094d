// The ITU-R BS.1770-4 K-weighting (a high shelf and the RLB high-pass), coefficients
// re-derived for any sample rate as in libebur128 (ebur128.c): the loudness of one channel
// (Loudness) and of several, summed as the standard sums them (ChannelPower).
#pragma once

#include <array>

#include "tactus/dsp/biquad.hpp"
#include "tactus/dsp/biquad_cascade.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class KWeighting {
  public:
    void prepare(const ProcessSpec& spec);
    void reset() noexcept {
        for (auto& section : sections_) section.reset();
    }
    int latency() const { return 0; }
    // Adds the square of each K-weighted sample to power[i].
    void add_power(const float* samples, float* power, int count) noexcept;
    // a.add_power(a_samples, ...), then b.add_power(b_samples, ...), in one wavefront
    // (dsp/biquad_cascade.hpp cascades_each): the same sums, in about half the time.
    static void add_power(KWeighting& a, const float* a_samples, KWeighting& b,
                          const float* b_samples, float* power, int count) noexcept;
    // For i < count, in order: sink(i, samples[i] K-weighted), in double.
    template <typename Sink>
    void each(const float* samples, int count, Sink sink) noexcept {
        cascade_each<2>(
            sections_.data(), count, [&](int i) { return static_cast<double>(samples[i]); }, sink);
    }

    static constexpr int kSections = 2;
    const Biquad* filters() const noexcept { return sections_.data(); }  // kSections in turn

  private:
    std::array<Biquad, kSections> sections_;  // the shelf, then the high-pass
};

}  // namespace tactus
