// The median of the last N values of a stream (the onset detector's adaptive threshold, the
// median of the recent flux: onset_detector.hpp). The values are kept twice, in arrival order (a
// ring) and sorted; a new value takes the oldest's place in both, by moving the sorted values
// between the two one place: two binary searches and at most N moves a value, where a selection
// over a copy each frame (std::nth_element) took several passes. Exactly that selection's value.
// Audio thread: median(), push(), fill(); prepare() allocates.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace tactus {

class SlidingMedian {
  public:
    void prepare(int length) {
        ring_.assign(static_cast<size_t>(std::max(1, length)), 0.0);
        sorted_ = ring_;
        oldest_ = 0;
    }
    // Every value at `value`: what was there before the stream.
    void fill(double value) noexcept {
        std::fill(ring_.begin(), ring_.end(), value);
        std::fill(sorted_.begin(), sorted_.end(), value);
        oldest_ = 0;
    }
    // The upper median of the last N values (the middle one for an odd N).
    double median() const noexcept { return sorted_[sorted_.size() / 2]; }
    // `value` in place of the oldest.
    void push(double value) noexcept {
        const double old = ring_[oldest_];
        ring_[oldest_] = value;
        oldest_ = oldest_ + 1 == ring_.size() ? 0 : oldest_ + 1;
        const auto at = std::lower_bound(sorted_.begin(), sorted_.end(), old);
        if (value > old) {  // the values in (old, value) move down one place
            const auto end = std::lower_bound(at + 1, sorted_.end(), value);
            std::move(at + 1, end, at);
            *(end - 1) = value;
        } else {  // those in (value, old) move up one place
            const auto begin = std::upper_bound(sorted_.begin(), at, value);
            std::move_backward(begin, at, at + 1);
            *begin = value;
        }
    }

  private:
    std::vector<double> ring_, sorted_;
    size_t oldest_ = 0;
};

}  // namespace tactus
