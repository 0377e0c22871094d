// FlatteningFilter: the measured response (sines through process(), steady-state RMS gain)
// follows target_db() within 1 dB over the P channel's 40-500 Hz at several sample rates (the
// largest deviation is printed), magnitude_db() describes what process() does, the filter never
// boosts in the band, the target is the inverted P-threshold curve, scaled by strength and
// bounded by range_db; designed for a contact area or an equal-sensation level, the measured
// response matches the model computed here from the perception functions within 1 dB (printed).
#include "tactus/post/flattening_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "support/signals.hpp"
#include "tactus/perception/sensation.hpp"
#include "tactus/perception/threshold.hpp"

namespace tactus {
namespace {

class FlatteningAtRate : public ::testing::TestWithParam<double> {};

TEST_P(FlatteningAtRate, MeasuredResponseFollowsTargetWithinOneDb) {
    const double fs = GetParam();
    FlatteningFilter design;
    design.prepare({.sample_rate_hz = fs},
                   {.low_hz = 20.0, .high_hz = 1000.0, .strength = 1.0, .range_db = 30.0});
    double worst = 0.0, worst_hz = 0.0, worst_design = 0.0;
    for (int i = 0; i <= 24; ++i) {
        const double f = 40.0 * std::pow(500.0 / 40.0, i / 24.0);
        FlatteningFilter filter;
        filter.prepare({.sample_rate_hz = fs},
                       {.low_hz = 20.0, .high_hz = 1000.0, .strength = 1.0, .range_db = 30.0});
        const double measured =
            test::measured_gain_db([&](float* x, int n) { filter.process(x, n); }, f, fs);
        const double deviation = measured - design.target_db(f);
        if (std::abs(deviation) > std::abs(worst)) worst = deviation, worst_hz = f;
        worst_design = std::max(worst_design, std::abs(measured - design.magnitude_db(f)));
        EXPECT_NEAR(measured, design.target_db(f), 1.0) << f << " Hz at " << fs << " Hz";
        // magnitude_db() reports what process() does.
        EXPECT_NEAR(measured, design.magnitude_db(f), 0.05) << f << " Hz at " << fs << " Hz";
    }
    std::cout << "[ flatten  ] " << fs
              << " Hz: max |measured - target| over 40-500 Hz = " << std::abs(worst) << " dB (at "
              << worst_hz << " Hz); max |measured - "
              << "magnitude_db| = " << worst_design << " dB\n";
}

TEST_P(FlatteningAtRate, NeverBoostsInTheBand) {
    const double fs = GetParam();
    for (double strength : {0.25, 1.0}) {
        for (double range : {10.0, 30.0, 40.0}) {
            FlatteningFilter design;
            design.prepare(
                {.sample_rate_hz = fs},
                {.low_hz = 20.0, .high_hz = 1000.0, .strength = strength, .range_db = range});
            for (double f = 20.0; f <= 1000.0; f *= 1.05)
                EXPECT_LE(design.magnitude_db(f), 0.5)
                    << f << " Hz, strength " << strength << ", range " << range;
            for (double f : {20.0, 40.0, 63.0, 1000.0}) {
                FlatteningFilter filter;
                filter.prepare(
                    {.sample_rate_hz = fs},
                    {.low_hz = 20.0, .high_hz = 1000.0, .strength = strength, .range_db = range});
                EXPECT_LE(
                    test::measured_gain_db([&](float* x, int n) { filter.process(x, n); }, f, fs),
                    0.5)
                    << f << " Hz, strength " << strength << ", range " << range;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Rates, FlatteningAtRate,
                         ::testing::Values(8000.0, 44100.0, 48000.0, 96000.0, 192000.0));

TEST(FlatteningFilter, TargetIsTheInvertedThresholdCurve) {
    FlatteningFilter filter;
    filter.prepare({.sample_rate_hz = 48000.0},
                   {.low_hz = 20.0, .high_hz = 1000.0, .strength = 1.0, .range_db = 40.0});
    // The least sensitive frequency of the band (40 Hz and, flat, below) passes at unity.
    const double reference = perception::p_threshold_db(40.0);
    EXPECT_NEAR(filter.target_db(40.0), 0.0, 1e-9);
    EXPECT_NEAR(filter.target_db(20.0), 0.0, 1e-9);
    for (double f : {63.0, 125.0, 250.0, 500.0, 1000.0})
        EXPECT_NEAR(filter.target_db(f), perception::p_threshold_db(f) - reference, 1e-9) << f;
    EXPECT_NEAR(filter.target_db(250.0), -20.0 - reference, 1e-9);  // deepest at 250 Hz

    filter.prepare({.sample_rate_hz = 48000.0},
                   {.low_hz = 20.0, .high_hz = 1000.0, .strength = 0.5, .range_db = 40.0});
    EXPECT_NEAR(filter.target_db(250.0), 0.5 * (-20.0 - reference), 1e-9);

    filter.prepare({.sample_rate_hz = 48000.0},
                   {.low_hz = 20.0, .high_hz = 1000.0, .strength = 1.0, .range_db = 12.0});
    for (double f = 20.0; f <= 1000.0; f *= 1.1) EXPECT_GE(filter.target_db(f), -12.0 - 1e-9);
    EXPECT_NEAR(filter.target_db(250.0), -12.0, 1e-9);
}

// The model's target for a contact area and a level above threshold, computed here from the
// perception functions: the P threshold curve (held below 40 Hz), relief scaled by the contour
// fraction, inverted so the least sensitive frequency is at 0 dB.
double model_target_db(double f, double area_cm2, double level_db, double range_db) {
    const auto contour = [&](double g) {
        return perception::threshold_db(perception::Channel::P, std::max(g, 40.0),
                                        {.contact_area_cm2 = area_cm2});
    };
    double highest = -1e9;
    for (double g = 20.0; g <= 1000.0; g *= 1.001) highest = std::max(highest, contour(g));
    highest = std::max(highest, contour(1000.0));
    return -std::min((highest - contour(f)) * perception::contour_relief_fraction(level_db),
                     range_db);
}

TEST(FlatteningFilter, DesignedFromTheModelForAreaAndLevel) {
    const double fs = 48000.0;
    double worst = 0.0;
    for (double area : {0.02, 0.5, 2.9}) {
        for (double level : {0.0, 20.0, 40.0}) {
            const FlatteningDesign d{.low_hz = 20.0,
                                     .high_hz = 1000.0,
                                     .range_db = 40.0,
                                     .contact_area_cm2 = area,
                                     .level_db = level};
            FlatteningFilter design;
            design.prepare({.sample_rate_hz = fs}, d);
            for (int i = 0; i <= 24; ++i) {
                const double f = 40.0 * std::pow(500.0 / 40.0, i / 24.0);
                EXPECT_NEAR(design.target_db(f), model_target_db(f, area, level, 40.0), 1e-3)
                    << f << " Hz, " << area << " cm2, " << level << " dB SL";
                FlatteningFilter filter;
                filter.prepare({.sample_rate_hz = fs}, d);
                const double measured =
                    test::measured_gain_db([&](float* x, int n) { filter.process(x, n); }, f, fs);
                const double deviation = std::abs(measured - model_target_db(f, area, level, 40.0));
                worst = std::max(worst, deviation);
                EXPECT_LE(deviation, 1.0) << f << " Hz, " << area << " cm2, " << level << " dB SL";
            }
        }
    }
    std::cout << "[ flatten  ] model designs (0.02/0.5/2.9 cm2 x 0/20/40 dB SL): max |measured - "
                 "model| over 40-500 Hz = "
              << worst << " dB\n";
}

TEST(FlatteningFilter, ContoursFlattenAsLevelRises) {
    // Relief 40 Hz vs 250 Hz: the full threshold relief at threshold, less at higher levels.
    double previous = 1e9;
    for (double level : {0.0, 20.0, 40.0, 60.0}) {
        FlatteningFilter filter;
        filter.prepare({.sample_rate_hz = 48000.0},
                       {.low_hz = 20.0, .high_hz = 1000.0, .range_db = 40.0, .level_db = level});
        const double relief = filter.target_db(40.0) - filter.target_db(250.0);
        EXPECT_LT(relief, previous) << level;
        previous = relief;
    }
    FlatteningFilter threshold;
    threshold.prepare({.sample_rate_hz = 48000.0},
                      {.low_hz = 20.0, .high_hz = 1000.0, .range_db = 40.0});
    EXPECT_NEAR(threshold.target_db(40.0) - threshold.target_db(250.0),
                perception::p_threshold_db(40.0) - perception::p_threshold_db(250.0), 1e-9);
}

TEST(FlatteningFilter, SmallerContactFlattensLessBelow80Hz) {
    // Spatial summation is absent at 40 Hz and full from 80 Hz, so a small contact raises the
    // threshold at 250 Hz but not at 40 Hz: less relief to compensate.
    FlatteningFilter large, small;
    large.prepare({.sample_rate_hz = 48000.0},
                  {.low_hz = 20.0, .high_hz = 1000.0, .range_db = 40.0});
    small.prepare({.sample_rate_hz = 48000.0},
                  {.low_hz = 20.0, .high_hz = 1000.0, .range_db = 40.0, .contact_area_cm2 = 0.1});
    const double large_relief = large.target_db(40.0) - large.target_db(250.0);
    const double small_relief = small.target_db(40.0) - small.target_db(250.0);
    EXPECT_NEAR(large_relief - small_relief, 3.0 * std::log2(2.9 / 0.1), 1e-6);
}

TEST(FlatteningFilter, ZeroStrengthIsFlat) {
    FlatteningFilter filter;
    filter.prepare({.sample_rate_hz = 48000.0},
                   {.low_hz = 20.0, .high_hz = 1000.0, .strength = 0.0, .range_db = 30.0});
    for (double f = 20.0; f <= 1000.0; f *= 1.1) {
        EXPECT_EQ(filter.target_db(f), 0.0);
        EXPECT_NEAR(filter.magnitude_db(f), 0.0, 0.05) << f;
    }
}

TEST(FlatteningFilter, ResetGivesTheSameOutputAgain) {
    FlatteningFilter filter;
    filter.prepare({.sample_rate_hz = 44100.0},
                   {.low_hz = 20.0, .high_hz = 1000.0, .strength = 1.0, .range_db = 30.0});
    std::vector<float> a = test::white_noise(8192, 3), b = a;
    filter.process(a.data(), static_cast<int>(a.size()));
    filter.reset();
    filter.process(b.data(), static_cast<int>(b.size()));
    EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace tactus
