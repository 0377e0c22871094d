#include "tactus/analysis/sample_history.hpp"

#include <algorithm>

#include "tactus/core/units.hpp"

namespace tactus {

void SampleHistory::prepare(int capacity_samples) {
    ring_.assign(static_cast<size_t>(next_power_of_two(capacity_samples)), 0.0f);
    mask_ = ring_.size() - 1;
    written_ = 0;
}

void SampleHistory::reset() noexcept {
    std::fill(ring_.begin(), ring_.end(), 0.0f);
    written_ = 0;
}

void SampleHistory::write(const float* samples, int count) noexcept {
    for (int i = 0; i < count; ++i) ring_[static_cast<uint64_t>(written_ + i) & mask_] = samples[i];
    written_ += count;
}

void SampleHistory::read_latest(float* out, int count) const noexcept {
    const int64_t start = written_ - count;
    for (int i = 0; i < count; ++i) out[i] = ring_[static_cast<uint64_t>(start + i) & mask_];
}

}  // namespace tactus
