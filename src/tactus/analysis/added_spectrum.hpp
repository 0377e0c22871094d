// What a hit adds to a stream of power spectra: at each onset the spectrum of the last frame that
// ended kMarginMs before the hit began is kept as what was already sounding (bass, chords, a
// voice, the previous hit's tail; the margin, so that a start estimated a little late does not
// count the hit's own beginning as the bed); every frame from then to the next onset, added() is
// the newest spectrum less that one, bin by bin, where positive. A stationary bed
// cancels; a hit over it reads as it would alone (the transient's energy above what was sounding).
// Audio thread: analyse(); prepare() allocates.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tactus/core/units.hpp"

namespace tactus {

// Frames back from the newest, which ended at analysis sample `now`, to the last that ended
// `margin_samples` or more before `start`, frames ending every `hop_samples`.
inline int64_t frames_back_before(int64_t now, int64_t start, int margin_samples,
                                  int hop_samples) noexcept {
    return (now - start + margin_samples + hop_samples - 1) / hop_samples;
}

class AddedSpectrum {
  public:
    static constexpr double kMarginMs = 1;
    // kMarginMs in samples at `sample_rate_hz` (RecentLoudest keeps the same margin).
    static int margin_samples(double sample_rate_hz) {
        return static_cast<int>(ms_to_samples(kMarginMs, sample_rate_hz));
    }

    // `longest_wait_samples`: the most analysis samples an onset's start can lie before the frame
    // that decides it (the ring of past spectra covers it).
    void prepare(int bins, int hop_samples, int longest_wait_samples, double sample_rate_hz);
    void reset() noexcept;
    // One frame ending at analysis sample `now`, and the start of an onset this frame decided
    // (< 0: none).
    void analyse(std::span<const float> powers, int64_t now, int64_t onset_start) noexcept;

    const std::vector<float>& added() const { return added_; }
    const std::vector<float>& reference() const { return reference_; }
    // Over every bin, bin by bin in double; summed when asked (most frames read no sum).
    double added_sum() const noexcept;

  private:
    std::vector<float> ring_;  // the last frames_ spectra, bins_ each
    std::vector<float> reference_, added_;
    int bins_ = 0, frames_ = 0, position_ = 0, hop_samples_ = 1, margin_samples_ = 0;
};

}  // namespace tactus
