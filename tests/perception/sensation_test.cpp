// Sensation level, the suprathreshold combination of channels (Hollins & Roy 1996) and the
// equal-sensation contour fraction.
#include "tactus/perception/sensation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tactus::perception {
namespace {

TEST(Sensation, LevelIsAboveThresholdOrZero) {
    EXPECT_DOUBLE_EQ(sensation_level_db(10.0, -20.0), 30.0);
    EXPECT_EQ(sensation_level_db(-25.0, -20.0), 0.0);
    EXPECT_EQ(sensation_level_db(-20.0, -20.0), 0.0);
}

TEST(Sensation, OneChannelCombinesToItself) {
    for (double sl : {0.0, 3.0, 20.0, 45.0})
        EXPECT_NEAR(combined_sensation_db({sl, 0, 0, 0}), sl, 1e-9);
    EXPECT_NEAR(combined_sensation_db({0, 0, 17.0, 0}), 17.0, 1e-9);
}

TEST(Sensation, StrongerPlusHalfTheWeaker) {
    // Magnitudes psi = 10^(0.89 SL/20) - 1; the combination is psi_strong + psi_weak / 2.
    const auto psi = [](double sl) { return std::pow(10.0, kMagnitudeExponent * sl / 20) - 1; };
    const double combined = combined_sensation_db({30.0, 20.0, 0, 0});
    EXPECT_NEAR(psi(combined), psi(30.0) + 0.5 * psi(20.0), 1e-9);
    // Order does not matter, and the weaker channel adds something but less than itself.
    EXPECT_NEAR(combined_sensation_db({20.0, 30.0, 0, 0}), combined, 1e-12);
    EXPECT_GT(combined, 30.0);
    EXPECT_LT(psi(combined), psi(30.0) + psi(20.0));
}

TEST(Sensation, ContourReliefShrinksWithLevel) {
    EXPECT_EQ(contour_relief_fraction(0.0), 1.0);
    EXPECT_EQ(contour_relief_fraction(-5.0), 1.0);
    EXPECT_NEAR(contour_relief_fraction(kContourFlatDb / 2), 0.5, 1e-12);
    EXPECT_EQ(contour_relief_fraction(kContourFlatDb + 10), 0.0);
}

}  // namespace
}  // namespace tactus::perception
