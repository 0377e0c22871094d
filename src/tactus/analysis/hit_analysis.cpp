#include "tactus/analysis/hit_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/fast_math.hpp"

namespace tactus {
namespace {
// A Hann-windowed sine of amplitude 1 centred on a bin reads power 1 there and 1/4 in each
// neighbour (stft_frame.hpp): 1.5 in all, for a mean power of 1/2.
constexpr double kSinePowerSum = 1.5;
constexpr double kFullScaleSineDb = -3.0103;
constexpr double kSilentDb = -120;
constexpr double kLowEdgeHz = 150, kMidEdgeHz = 1000, kHighEdgeHz = 3000;

double power_db(double power_sum) {
    return power_sum > 0 ? std::max(kSilentDb, 10 * std::log10(power_sum / kSinePowerSum) +
                                                   kFullScaleSineDb)
                         : kSilentDb;
}
}  // namespace

void HitAnalysis::prepare(int bins, double bin_hz, double sample_rate_hz, int hop_samples,
                          int longest_wait_samples, const HitSettings& settings) {
    bins_ = bins;
    hop_samples_ = std::max(1, hop_samples);
    sample_rate_hz_ = sample_rate_hz;
    frames_ = longest_wait_samples / hop_samples_ + 2;
    ring_.assign(static_cast<size_t>(frames_) * static_cast<size_t>(bins_), 0.0f);
    reference_.assign(static_cast<size_t>(bins_), 0.0f);
    added_.assign(static_cast<size_t>(bins_), 0.0f);
    added_magnitude_.assign(static_cast<size_t>(bins_), 0.0f);
    const auto bin_of = [&](double hz) {
        return std::clamp(static_cast<int>(std::ceil(hz / bin_hz)), 1, bins_);
    };
    low_bins_ = bin_of(kLowEdgeHz);
    mid_bins_ = bin_of(kMidEdgeHz);
    high_bin_ = bin_of(kHighEdgeHz);
    brightness_.prepare(bins, bin_hz, settings.brightness_max_hz);
    set_live(settings);
    reset();
}

void HitAnalysis::set_live(const HitSettings& settings) noexcept {
    brightness_.set_max_hz(settings.brightness_max_hz);
    settle_samples_ = std::llround(settings.settle_ms * 1e-3 * sample_rate_hz_);
}

void HitAnalysis::reset() noexcept {
    std::fill(ring_.begin(), ring_.end(), 0.0f);
    std::fill(reference_.begin(), reference_.end(), 0.0f);
    position_ = 0;
    hit_start_ = -1;
    level_db_ = peak_db_ = kSilentDb;
    brightness_hz_ = 0;
    part_ = DrumPart::other;
    part_decided_ = deciding_ = false;
}

const float* HitAnalysis::past(int frames_back) const noexcept {
    const int slot = (position_ + frames_ - std::clamp(frames_back, 0, frames_ - 1)) % frames_;
    return ring_.data() + static_cast<size_t>(slot) * static_cast<size_t>(bins_);
}

void HitAnalysis::analyse(std::span<const float> powers, int64_t now,
                          int64_t onset_start) noexcept {
    position_ = (position_ + 1) % frames_;
    std::copy_n(powers.data(), bins_, ring_.data() + static_cast<size_t>(position_) * bins_);
    if (onset_start >= 0) {
        // The last frame that ended at or before the hit's start: what was already sounding.
        const auto back = static_cast<int>((now - onset_start + hop_samples_ - 1) / hop_samples_);
        std::copy_n(past(back), bins_, reference_.data());
        hit_start_ = onset_start;
        peak_db_ = kSilentDb;
        deciding_ = true;
    }
    double total = 0;
    for (int k = 0; k < bins_; ++k) {
        added_[k] = std::max(0.0f, powers[k] - reference_[k]);
        added_magnitude_[k] = std::sqrt(added_[k]);
        total += added_[k];
    }
    level_db_ = power_db(total);
    peak_db_ = std::max(peak_db_, level_db_);
    brightness_hz_ = brightness_.centroid_hz(added_magnitude_);
    part_decided_ = false;
    if (deciding_ && now - hit_start_ >= settle_samples_) {
        part_ = classify();
        part_decided_ = true;
        deciding_ = false;
    }
}

DrumPart HitAnalysis::classify() const noexcept {
    const double low = sum_of(added_.data() + 1, low_bins_ - 1);
    const double mid = sum_of(added_.data() + low_bins_, mid_bins_ - low_bins_);
    const double upper = sum_of(added_.data() + mid_bins_, high_bin_ - mid_bins_);
    const double high = sum_of(added_.data() + high_bin_, bins_ - high_bin_);
    const double total = low + mid + upper + high + 1e-30;
    if (low / total > 0.3) return DrumPart::kick;
    if (high / total > 0.5) return DrumPart::hat;
    return DrumPart::snare;
}

}  // namespace tactus
