#include "tactus/analysis/added_spectrum.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/vector_clones.hpp"

namespace tactus {

void AddedSpectrum::prepare(int bins, int hop_samples, int longest_wait_samples,
                            double sample_rate_hz) {
    bins_ = bins;
    hop_samples_ = std::max(1, hop_samples);
    margin_samples_ = margin_samples(sample_rate_hz);
    frames_ = (longest_wait_samples + margin_samples_) / hop_samples_ + 2;
    ring_.assign(static_cast<size_t>(frames_) * static_cast<size_t>(bins_), 0.0f);
    reference_.assign(static_cast<size_t>(bins_), 0.0f);
    added_.assign(static_cast<size_t>(bins_), 0.0f);
    reset();
}

void AddedSpectrum::reset() noexcept {
    std::fill(ring_.begin(), ring_.end(), 0.0f);
    std::fill(reference_.begin(), reference_.end(), 0.0f);
    std::fill(added_.begin(), added_.end(), 0.0f);
    position_ = 0;
}

TACTUS_VECTOR_CLONES void AddedSpectrum::analyse(std::span<const float> powers, int64_t now,
                                                 int64_t onset_start) noexcept {
    position_ = (position_ + 1) % frames_;
    std::copy_n(powers.data(), bins_, ring_.data() + static_cast<size_t>(position_) * bins_);
    if (onset_start >= 0) {
        // The last frame that ended kMarginMs or more before the hit's start.
        const auto back = static_cast<int>(std::min<int64_t>(
            frames_back_before(now, onset_start, margin_samples_, hop_samples_), frames_ - 1));
        const int slot = (position_ + frames_ - back) % frames_;
        std::copy_n(ring_.data() + static_cast<size_t>(slot) * bins_, bins_, reference_.data());
    }
    for (int k = 0; k < bins_; ++k) added_[k] = std::max(0.0f, powers[k] - reference_[k]);
}

double AddedSpectrum::added_sum() const noexcept {
    double sum = 0;
    for (int k = 0; k < bins_; ++k) sum += added_[k];
    return sum;
}

}  // namespace tactus
