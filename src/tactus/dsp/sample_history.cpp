#include "tactus/dsp/sample_history.hpp"

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
    const auto skipped = std::max<int64_t>(0, count - static_cast<int64_t>(ring_.size()));
    written_ += skipped;  // only the newest ring-full can be kept
    samples += skipped;
    count -= static_cast<int>(skipped);
    const auto start = static_cast<uint64_t>(written_) & mask_;
    const auto first = std::min<uint64_t>(static_cast<uint64_t>(count), ring_.size() - start);
    std::copy_n(samples, first, ring_.data() + start);
    std::copy_n(samples + first, count - first, ring_.data());
    written_ += count;
}

void SampleHistory::read_latest(float* out, int count) const noexcept {
    const auto start = static_cast<uint64_t>(written_ - count) & mask_;  // ring holds zeros
    const auto first = std::min<uint64_t>(static_cast<uint64_t>(count), ring_.size() - start);
    std::copy_n(ring_.data() + start, first, out);
    std::copy_n(ring_.data(), count - first, out + first);
}

}  // namespace tactus
