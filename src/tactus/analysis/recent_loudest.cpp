#include "tactus/analysis/recent_loudest.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/analysis/added_spectrum.hpp"
#include "tactus/core/units.hpp"

namespace tactus {
namespace {
constexpr double kFloorPower = 1e-12;  // -120 dB re a full-scale sine's
constexpr double kRiseLimit = 6;       // log10 of a power's rise
}  // namespace

void RecentLoudest::prepare(int hop_samples, double sample_rate_hz, int longest_wait_samples) {
    hop_samples_ = std::max(1, hop_samples);
    margin_samples_ = AddedSpectrum::margin_samples(sample_rate_hz);
    span_frames_ = std::max(
        kWindowFrames, static_cast<int>(ms_to_samples(kSpanMs, sample_rate_hz)) / hop_samples_);
    frames_ = (longest_wait_samples + margin_samples_) / hop_samples_ + span_frames_ + 2;
    ring_.assign(static_cast<size_t>(frames_), 0.0);
    reset();
}

void RecentLoudest::reset() noexcept {
    std::fill(ring_.begin(), ring_.end(), 0.0);
    position_ = 0;
}

void RecentLoudest::push(double power) noexcept {
    position_ = position_ + 1 == frames_ ? 0 : position_ + 1;
    ring_[static_cast<size_t>(position_)] = power;
}

float RecentLoudest::rise(int64_t now, int64_t start) const noexcept {
    // Frames since the start (at least the newest), and the newest that ended a margin before it.
    const auto since = static_cast<int>(
        std::clamp<int64_t>(frames_back_before(now, start, 0, hop_samples_), 1, kWindowFrames));
    double power_now = 0;
    for (int j = 0; j < since; ++j) power_now += back(j) / since;
    const auto before = static_cast<int>(std::min<int64_t>(
        frames_back_before(now, start, margin_samples_, hop_samples_), frames_ - 1));
    double loudest = 0;
    for (int j = before; j + kWindowFrames - 1 < std::min(before + span_frames_, frames_); ++j) {
        double window = 0;
        for (int k = 0; k < kWindowFrames; ++k) window += back(j + k) / kWindowFrames;
        loudest = std::max(loudest, window);
    }
    return static_cast<float>(std::clamp(
        std::log10((power_now + kFloorPower) / (loudest + kFloorPower)), -kRiseLimit, kRiseLimit));
}

}  // namespace tactus
