#include "tactus/post/peak_limiter.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/core/vector_clones.hpp"

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
    fresh_sum_ = 0;
}

namespace {
// The static curve for the levels now (PeakLimiter::curve).
double curve_at(double peak, double threshold, double ceiling) noexcept {
    if (peak <= threshold) return peak;
    const double knee = ceiling - threshold;
    if (knee <= 0.0) return ceiling;
    const double u = (peak - threshold) / knee;
    return threshold + knee * u / (1.0 + u);
}
}  // namespace

double PeakLimiter::curve(double peak) const noexcept {
    return curve_at(peak, threshold_, ceiling_);
}

// The state in locals for the block (kept in registers), written back at its end.
TACTUS_VECTOR_CLONES void PeakLimiter::process(float* samples, int count) noexcept {
    const size_t capacity = minimum_.size();
    const auto length = static_cast<size_t>(lookahead_);
    const int64_t lookahead = lookahead_;
    const double release = release_;
    double drive = drive_, threshold = threshold_, ceiling = ceiling_;
    int glide_left = glide_left_;
    std::pair<int64_t, double>* const minimum = minimum_.data();
    double* const held_gain = held_gain_.data();
    double* const delay = delay_.data();
    size_t minimum_head = minimum_head_, minimum_size = minimum_size_, slot = slot_;
    int64_t time = time_;
    double released_gain = released_gain_, box_sum = box_sum_, fresh_sum = fresh_sum_;
    for (int i = 0; i < count; ++i) {
        if (glide_left > 0) {
            if (--glide_left == 0) {
                drive = target_.drive, threshold = target_.threshold, ceiling = target_.ceiling;
            } else {
                drive += step_.drive, threshold += step_.threshold, ceiling += step_.ceiling;
            }
        }
        double x = samples[i];
        if (!std::isfinite(x)) x = 0.0;
        x *= drive;
        const double magnitude = std::abs(x);
        const double wanted =  // at most 1, whatever the curve's rounding
            magnitude > threshold
                ? std::min(1.0, curve_at(magnitude, threshold, ceiling) / magnitude)
                : 1.0;

        // Sliding minimum of the wanted gain over the last lookahead + 1 samples: every gain
        // averaged into a sample's output below has seen that sample's wish. The queue holds the
        // gains below 1 (a sample below the knee, most of them, leaves it alone): 1 when empty.
        // Ring positions wrap by comparison: no integer division per sample.
        const auto wrap = [capacity](size_t i) { return i >= capacity ? i - capacity : i; };
        if (wanted < 1.0) {
            while (minimum_size > 0 &&
                   minimum[wrap(minimum_head + minimum_size - 1)].second >= wanted)
                --minimum_size;
            minimum[wrap(minimum_head + minimum_size)] = {time, wanted};
            ++minimum_size;
        }
        if (minimum_size > 0 && minimum[minimum_head].first < time - lookahead) {
            minimum_head = wrap(minimum_head + 1);
            --minimum_size;
        }
        const double held = minimum_size > 0 ? minimum[minimum_head].second : 1.0;

        // Instant attack, one-pole release, never above the held gain.
        released_gain = std::min(held, held + release * (released_gain - held));

        // Box average over the look-ahead, aligned with the delayed sample.
        box_sum += released_gain - held_gain[slot];
        held_gain[slot] = released_gain;
        fresh_sum += released_gain;
        if (slot == length - 1) {  // re-sum once per look-ahead: no rounding drift
            box_sum = fresh_sum;
            fresh_sum = 0;
        }
        const double gain = std::min(1.0, box_sum / static_cast<double>(length));

        const double delayed = delay[slot];
        delay[slot] = x;
        const double y = std::clamp(delayed * gain, -ceiling, ceiling);
        samples[i] = static_cast<float>(y);
        ++time;
        if (++slot == length) slot = 0;
    }
    drive_ = drive, threshold_ = threshold, ceiling_ = ceiling;
    glide_left_ = glide_left;
    minimum_head_ = minimum_head, minimum_size_ = minimum_size, slot_ = slot;
    time_ = time;
    released_gain_ = released_gain, box_sum_ = box_sum, fresh_sum_ = fresh_sum;
}

}  // namespace tactus
