// The onset model's rise of the highs over their recent loudest (analysis/onset_rises.hpp): the
// 6-10 kHz band's power (analysis/band_power.hpp, plain, one analysis frame at a time, at the
// input rate) over the last two frames up to an onset's decision, from its start on, against its
// loudest over two frames among those that ended in the 50 ms before the start (and
// AddedSpectrum::kMarginMs or more before it, as what was sounding is kept). A voice's sibilants
// and a pad's shimmer swell and fade from one moment to the next, so rising over the moment just
// before the onset says little; a drum's noise rises over the mix's loudest highs of the last
// 50 ms. The spectra's Hann windows weigh a frame's newest milliseconds, where the decision finds
// the hit, near zero: read through them the same rise told drums from the bed worse than chance
// (area under the ROC curve 0.39-0.45 over the music corpus's onsets over a bed).
// Audio thread: push(), rise(); prepare() allocates.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tactus {

class RecentLoudest {
  public:
    static constexpr double kSpanMs = 50;
    static constexpr int kWindowFrames = 2;

    // `longest_wait_samples`: the most analysis samples an onset's start can lie before the
    // frame that decides it.
    void prepare(int hop_samples, double sample_rate_hz, int longest_wait_samples);
    void reset() noexcept;
    // The power of the frame ending now.
    void push(double power) noexcept;
    // log10 of the power since the onset's start (at most kWindowFrames frames) over the recent
    // loudest, within +-6; `now` and `start` in analysis samples.
    float rise(int64_t now, int64_t start) const noexcept;

  private:
    double back(int frames) const noexcept {  // the power frames back (0: the newest)
        return ring_[static_cast<size_t>((position_ + frames_ - frames) % frames_)];
    }

    std::vector<double> ring_;
    int hop_samples_ = 1, margin_samples_ = 0, span_frames_ = 1, frames_ = 1, position_ = 0;
};

}  // namespace tactus
