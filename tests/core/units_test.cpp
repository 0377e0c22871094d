// Unit conversions: dB <-> gain/power, ms -> samples (rounded), one-pole coefficients (a step
// reaches 1 - 1/e after one time constant), next_power_of_two.
#include "tactus/core/units.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tactus {
namespace {

TEST(Units, Decibels) {
    EXPECT_DOUBLE_EQ(db_to_gain(0), 1.0);
    EXPECT_NEAR(db_to_gain(-6.0205999), 0.5, 1e-8);
    EXPECT_NEAR(db_to_gain(20), 10.0, 1e-12);
    EXPECT_NEAR(gain_to_db(2.0), 6.0205999, 1e-6);
    EXPECT_NEAR(power_to_db(2.0), 3.0103, 1e-4);
    for (double db = -120; db <= 40; db += 7.5) EXPECT_NEAR(gain_to_db(db_to_gain(db)), db, 1e-9);
}

TEST(Units, MillisecondsToSamples) {
    EXPECT_EQ(ms_to_samples(2.9, 48000), 139);
    EXPECT_EQ(ms_to_samples(2.9, 44100), 128);
    EXPECT_EQ(ms_to_samples(1000, 8000), 8000);
    EXPECT_EQ(ms_to_samples(0, 48000), 0);
}

TEST(Units, OnePoleCoefficient) {
    EXPECT_EQ(one_pole_coefficient(0, 48000), 0.0);
    EXPECT_EQ(one_pole_coefficient(-5, 48000), 0.0);
    const double c = one_pole_coefficient(10, 48000);
    double y = 0.0;
    for (int i = 0; i < 480; ++i) y = 1.0 + c * (y - 1.0);
    EXPECT_NEAR(y, 1.0 - std::exp(-1.0), 1e-9);
    EXPECT_NEAR(one_pole_coefficient(10, 48000, 48), std::pow(c, 48), 1e-12);
}

TEST(Units, NextPowerOfTwo) {
    EXPECT_EQ(next_power_of_two(0), 1);
    EXPECT_EQ(next_power_of_two(1), 1);
    EXPECT_EQ(next_power_of_two(2), 2);
    EXPECT_EQ(next_power_of_two(3), 4);
    EXPECT_EQ(next_power_of_two(1114), 2048);
    EXPECT_EQ(next_power_of_two(4096), 4096);
}

}  // namespace
}  // namespace tactus
