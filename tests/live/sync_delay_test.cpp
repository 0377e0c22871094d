// --sync's delay while `tactus live` runs: the delay line moves without a click (a crossfade
// between the old and the new read positions, exact delays before and after it), never beyond
// the ring allocated at the start; the delay is measured again when the settings change, and
// the table's slowest settings fit in that ring.
#include "live/sync_delay.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "live/sound_delay.hpp"
#include "tactus/core/units.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus::live {
namespace {

constexpr double kRateHz = 44100;

std::vector<float> tone(size_t n) {  // a steady tone: any jump in it is a click
    std::vector<float> x(n);
    for (size_t i = 0; i < n; ++i)
        x[i] = static_cast<float>(0.5 *
                                  std::sin(2 * kPi * 220 * static_cast<double>(i) / kRateHz + 0.3));
    return x;
}

// Runs x through `delay` in blocks of `block`, asking for `next_delay` at sample `change_at`.
std::vector<float> delayed(SoundDelay& delay, const std::vector<float>& x, int block,
                           size_t change_at, int next_delay) {
    std::vector<float> y = x;
    for (size_t at = 0; at < y.size(); at += static_cast<size_t>(block)) {
        if (at <= change_at && change_at < at + static_cast<size_t>(block))
            delay.set_delay_samples(next_delay);
        float* channel = y.data() + at;
        delay.process(&channel, static_cast<int>(std::min<size_t>(block, y.size() - at)));
    }
    return y;
}

TEST(SoundDelay, MovesToTheNewDelayByACrossfadeWithoutAClick) {
    const std::vector<float> x = tone(20000);
    constexpr int kFrom = 113, kTo = 203, kFade = 441, kBlock = 64;
    for (const auto& [from, to] : {std::pair{kFrom, kTo}, std::pair{kTo, kFrom}}) {
        SoundDelay delay(1, 1000, from, kFade);
        const std::vector<float> y = delayed(delay, x, kBlock, 5000, to);
        const auto a = [&](size_t n) {
            return n >= static_cast<size_t>(from) ? x[n - from] : 0.0f;
        };
        const auto b = [&](size_t n) { return n >= static_cast<size_t>(to) ? x[n - to] : 0.0f; };
        size_t first_b = y.size(), last_a = 0;  // the crossfade lies between
        for (size_t n = 0; n < y.size(); ++n) {
            if (y[n] == a(n)) last_a = n;
            if (y[n] != b(n)) first_b = n + 1;
        }
        EXPECT_EQ(last_a + 1, 4992u) << "the old delay up to the block of the change";
        EXPECT_EQ(first_b, 4992u + kFade - 1) << "the new delay after one crossfade";
        EXPECT_EQ(delay.delay_samples(), to);
        float largest_step = 0, allowed = 0;
        for (size_t n = kTo + 1; n < y.size(); ++n) {  // both positions in the tone
            largest_step = std::max(largest_step, std::abs(y[n] - y[n - 1]));
            allowed = std::max({allowed, std::abs(a(n) - a(n - 1)), std::abs(b(n) - b(n - 1))});
        }
        // The tone's own largest step, plus the crossfade's share of the two positions' gap.
        EXPECT_LE(largest_step, allowed + 1.0f / kFade + 1e-6f) << from << " -> " << to;
        // An immediate move would step by the gap between the two positions.
        EXPECT_GT(std::abs(a(4992) - b(4992)), 20 * (allowed + 1.0f / kFade));
    }
}

TEST(SoundDelay, ClampsToItsRingAndFinishesOneMoveBeforeTheNext) {
    SoundDelay delay(2, 300, 5000, 100);
    EXPECT_EQ(delay.delay_samples(), 300) << "the ring holds 300 at most";
    delay.set_delay_samples(-4);
    EXPECT_EQ(delay.delay_samples(), 0);
    std::vector<float> left(1000), right(1000);
    for (size_t i = 0; i < left.size(); ++i) left[i] = right[i] = static_cast<float>(i);
    float* channels[] = {left.data(), right.data()};
    delay.set_delay_samples(10);
    delay.process(channels, 50);  // a move from 300 to 10 begins...
    delay.set_delay_samples(20);  // ...and this one waits for it
    float* next[] = {left.data() + 50, right.data() + 50};
    delay.process(next, 450);  // the first move ends; the second one begins in the next call
    float* last[] = {left.data() + 500, right.data() + 500};
    delay.process(last, 500);
    EXPECT_EQ(left, right) << "every channel delayed alike";
    EXPECT_FLOAT_EQ(left[999], 999 - 20);
}

TEST(VibrationDelay, MeasuredAgainWhenTheSettingsChange) {
    Settings settings;
    VibrationDelay delay(settings, kRateHz, std::nullopt);
    const int first = delay.samples();
    EXPECT_EQ(first, vibration_delay_samples(settings, kRateHz, std::nullopt));
    EXPECT_FALSE(delay.follow(settings, 1.0)) << "the same settings: nothing to measure";
    settings.set(P::analysis_hop_ms, 5);
    EXPECT_TRUE(delay.follow(settings, 1.0));
    EXPECT_EQ(delay.samples(), vibration_delay_samples(settings, kRateHz, std::nullopt));
    // A longer hop decides onsets later: about half of the 3.55 ms more, on average.
    EXPECT_GT(delay.samples() - first, ms_to_samples(1.0, kRateHz))
        << first << " -> " << delay.samples();
    settings.set(P::analysis_hop_ms, 1.45);
    EXPECT_FALSE(delay.follow(settings, 1.0 + VibrationDelay::kRemeasurePeriodS / 2))
        << "a sweep is measured at most every kRemeasurePeriodS";
    EXPECT_TRUE(delay.follow(settings, 1.01 + VibrationDelay::kRemeasurePeriodS));
    EXPECT_EQ(delay.samples(), first);
}

// The ring is allocated once for max_vibration_delay_samples(): the slowest settings the table
// allows (every time at its longest) are measured within it.
TEST(VibrationDelay, TheSlowestSettingsFitTheRing) {
    Settings slow;
    for (const P id : {P::analysis_hop_ms, P::analysis_window_ms, P::onset_window_ms,
                       P::post_lookahead_ms, P::envelope_attack_ms})
        slow.set(id, spec(id).max);
    const int measured = vibration_delay_samples(slow, kRateHz, std::nullopt);
    EXPECT_GT(measured, ms_to_samples(20.0, kRateHz)) << "at least the look-ahead";
    EXPECT_LT(measured, max_vibration_delay_samples(kRateHz));
}

}  // namespace
}  // namespace tactus::live
