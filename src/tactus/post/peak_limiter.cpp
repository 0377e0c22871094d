#include "tactus/post/peak_limiter.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "tactus/core/units.hpp"

namespace tactus {

PeakLimiter::Gains PeakLimiter::gains_of(const LimiterLevels& l) noexcept {
    return {.drive = db_to_gain(l.drive_db),
            .threshold = l.ceiling * db_to_gain(l.threshold_db),
            .ceiling = float_at_most(l.ceiling)};  // output samples are floats
}

void PeakLimiter::prepare(const ProcessSpec& spec, double lookahead_ms,
                          const LimiterLevels& levels) {
    const double sample_rate_hz = spec.sample_rate_hz;
    sample_rate_hz_ = sample_rate_hz;
    lookahead_ = std::max<int>(1, static_cast<int>(ms_to_samples(lookahead_ms, sample_rate_hz)));
    set_levels(levels, 0);
    delay_.assign(static_cast<size_t>(lookahead_), 0.0);
    held_gain_.assign(static_cast<size_t>(lookahead_), 1.0);
    minimum_.assign(static_cast<size_t>(lookahead_) + 2, {0, 1.0});
    reset();
}

void PeakLimiter::set_levels(const LimiterLevels& levels, int samples) noexcept {
    release_ = one_pole_coefficient(levels.release_ms, sample_rate_hz_);
    target_ = gains_of(levels);
    glide_left_ = std::max(0, samples);
    if (glide_left_ == 0) {
        drive_ = target_.drive, threshold_ = target_.threshold, ceiling_ = target_.ceiling;
        return;
    }
    step_ = {(target_.drive - drive_) / glide_left_, (target_.threshold - threshold_) / glide_left_,
             (target_.ceiling - ceiling_) / glide_left_};
}

void PeakLimiter::reset() noexcept {
    std::fill(delay_.begin(), delay_.end(), 0.0);
    std::fill(held_gain_.begin(), held_gain_.end(), 1.0);
    minimum_head_ = minimum_size_ = 0;
    time_ = 0;
    slot_ = 0;
    released_gain_ = 1.0;
    box_sum_ = static_cast<double>(lookahead_);
}

double PeakLimiter::curve(double peak) const noexcept {
    if (peak <= threshold_) return peak;
    const double knee = ceiling_ - threshold_;
    if (knee <= 0.0) return ceiling_;
    const double u = (peak - threshold_) / knee;
    return threshold_ + knee * u / (1.0 + u);
}

void PeakLimiter::process(float* samples, int count) noexcept {
    const size_t capacity = minimum_.size();
    const auto length = static_cast<size_t>(lookahead_);
    for (int i = 0; i < count; ++i) {
        if (glide_left_ > 0) {
            if (--glide_left_ == 0) {
                drive_ = target_.drive, threshold_ = target_.threshold, ceiling_ = target_.ceiling;
            } else {
                drive_ += step_.drive, threshold_ += step_.threshold, ceiling_ += step_.ceiling;
            }
        }
        double x = samples[i];
        if (!std::isfinite(x)) x = 0.0;
        x *= drive_;
        const double magnitude = std::abs(x);
        const double wanted = magnitude > threshold_ ? curve(magnitude) / magnitude : 1.0;

        // Sliding minimum of the wanted gain over the last lookahead + 1 samples: every gain
        // averaged into a sample's output below has seen that sample's wish.
        // Ring positions wrap by comparison: no integer division per sample.
        const auto wrap = [capacity](size_t i) { return i >= capacity ? i - capacity : i; };
        while (minimum_size_ > 0 &&
               minimum_[wrap(minimum_head_ + minimum_size_ - 1)].second >= wanted)
            --minimum_size_;
        minimum_[wrap(minimum_head_ + minimum_size_)] = {time_, wanted};
        ++minimum_size_;
        if (minimum_[minimum_head_].first < time_ - lookahead_) {
            minimum_head_ = wrap(minimum_head_ + 1);
            --minimum_size_;
        }
        const double held = minimum_[minimum_head_].second;

        // Instant attack, one-pole release, never above the held gain.
        released_gain_ = std::min(held, held + release_ * (released_gain_ - held));

        // Box average over the look-ahead, aligned with the delayed sample.
        const size_t slot = slot_;
        box_sum_ += released_gain_ - held_gain_[slot];
        held_gain_[slot] = released_gain_;
        if (slot == length - 1)  // re-sum once per look-ahead: no rounding drift, O(1) a sample
            box_sum_ = std::accumulate(held_gain_.begin(), held_gain_.end(), 0.0);
        const double gain = std::min(1.0, box_sum_ / static_cast<double>(length));

        const double delayed = delay_[slot];
        delay_[slot] = x;
        const double y = std::clamp(delayed * gain, -ceiling_, ceiling_);
        samples[i] = static_cast<float>(y);
        ++time_;
        if (++slot_ == length) slot_ = 0;
    }
}

}  // namespace tactus
