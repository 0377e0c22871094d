// The rise of each of `width` values over the loudest it was over its frames `lag` to `span`
// back (SuperFlux's temporal maximum, Böck & Widmer 2013): a noise value must beat them all to
// count, a new sound beats them all. A ring of the last `span` frames; each frame takes the
// oldest's place. The onset detector's spectrum bins and its two bands (onset_detector.hpp).
// Audio thread: fill(), rise(); prepare() allocates.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tactus {

class TemporalMax {
  public:
    // 1 <= lag_frames <= span_frames (a shorter span is taken as the lag).
    void prepare(int width, int lag_frames, int span_frames) {
        width_ = width;
        lag_ = lag_frames;
        span_ = std::max(lag_frames, span_frames);
        past_.assign(static_cast<size_t>(span_) * static_cast<size_t>(width_), 0.0f);
        loudest_.assign(static_cast<size_t>(width_), 0.0f);
        position_ = 0;
    }
    // Every past frame at `value`: what was there before the stream.
    void fill(float value) noexcept {
        std::fill(past_.begin(), past_.end(), value);
        position_ = 0;
    }
    // rise[k] = max(0, now[k] - the loudest of value k over the frames lag to span back); then
    // `now` is the newest frame. Inline, so it is built with its caller's vector clones.
    void rise(const float* now, float* rise) noexcept {
        float* oldest = frame(span_);
        std::copy(oldest, oldest + width_, loudest_.data());
        for (int back = lag_; back < span_; ++back) {
            const float* past = frame(back);
            for (int k = 0; k < width_; ++k) loudest_[k] = std::max(loudest_[k], past[k]);
        }
        for (int k = 0; k < width_; ++k) {
            rise[k] = std::max(0.0f, now[k] - loudest_[k]);
            oldest[k] = now[k];
        }
        position_ = (position_ + 1) % span_;
    }

    // The same for one value (width 1).
    float rise(float now) noexcept {
        float* oldest = frame(span_);
        float loudest = *oldest;
        for (int back = lag_; back < span_; ++back) loudest = std::max(loudest, *frame(back));
        *oldest = now;
        position_ = (position_ + 1) % span_;
        return std::max(0.0f, now - loudest);
    }

  private:
    float* frame(int frames_back) noexcept {
        return past_.data() + static_cast<size_t>((position_ + span_ - frames_back) % span_) *
                                  static_cast<size_t>(width_);
    }

    std::vector<float> past_, loudest_;
    int width_ = 1, lag_ = 1, span_ = 1, position_ = 0;
};

}  // namespace tactus
