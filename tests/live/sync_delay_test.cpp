// --sync's delay while `tactus live` runs (its delay line: tests/dsp/delay_line_test.cpp): the
// delay is measured again when the settings change, and the table's slowest settings fit in
// the ring allocated at the start.
#include "live/sync_delay.hpp"

#include <gtest/gtest.h>

#include "tactus/core/units.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus::live {
namespace {

constexpr double kRateHz = 44100;

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
