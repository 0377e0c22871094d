// P-channel threshold curve: minimum T_min = -20 dB at f_m = 250 Hz, 12 dB/octave below and
// 9 dB/octave above asymptotically, with the documented closed form.
#include "tactus/perception/threshold.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tactus::perception {
namespace {

TEST(PThreshold, MinimumAtBestFrequency) {
    EXPECT_NEAR(p_threshold_db(kPBestHz), kPMinimumDb, 1e-12);
    for (double f = 40; f <= 1000; f *= 1.01)
        EXPECT_GE(p_threshold_db(f), kPMinimumDb - 1e-12) << f;
    EXPECT_LT(p_threshold_db(245), p_threshold_db(200));
    EXPECT_LT(p_threshold_db(255), p_threshold_db(300));
}

TEST(PThreshold, AsymptoticSlopes) {
    const double octave_low = p_threshold_db(10) - p_threshold_db(20);
    const double octave_high = p_threshold_db(8000) - p_threshold_db(4000);
    EXPECT_NEAR(octave_low, 12.04, 0.05);  // (f_m/f)^4: 40 log10 2 dB per octave
    EXPECT_NEAR(octave_high, 9.03, 0.05);  // (f/f_m)^3: 30 log10 2
}

TEST(PThreshold, ClosedForm) {
    for (double f : {40.0, 100.0, 500.0}) {
        const double r = f / 250.0;
        EXPECT_NEAR(p_threshold_db(f),
                    -20 + 10 * std::log10(3.0 / 7.0 * std::pow(r, -4) + 4.0 / 7.0 * std::pow(r, 3)),
                    1e-9);
    }
}

}  // namespace
}  // namespace tactus::perception
