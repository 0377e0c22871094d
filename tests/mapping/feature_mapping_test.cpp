// FeatureMapping: lin, log and exp curves at their endpoints and midpoints (arithmetic for lin,
// geometric for log, dB-linear for exp), clamping outside the input range, inverted ranges
// (in_min > in_max), one-pole smoothing with the set time constant, and source selection.
#include "tactus/mapping/feature_mapping.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tactus {
namespace {

// A mapping of the given group with its settings, at 1000 frames per second.
FeatureMapping make(P first, double in_min, double in_max, double out_min, double out_max,
                    MappingCurve curve, double smoothing_ms = 0.0,
                    FeatureSource source = FeatureSource::loudness_db) {
    Settings s;
    const auto at = [first](int k) { return static_cast<P>(static_cast<int>(first) + k); };
    s.set(at(0), static_cast<double>(source));
    s.set(at(1), in_min);
    s.set(at(2), in_max);
    s.set(at(3), out_min);
    s.set(at(4), out_max);
    s.set(at(5), static_cast<double>(curve));
    s.set(at(6), smoothing_ms);
    FeatureMapping m;
    m.prepare(s, first, 1000.0);
    return m;
}

TEST(FeatureMapping, LinearCurve) {
    const auto m = make(P::amplitude_source, 0, 10, 0.2, 0.8, MappingCurve::lin);
    EXPECT_DOUBLE_EQ(m.shape(0), 0.2);
    EXPECT_DOUBLE_EQ(m.shape(10), 0.8);
    EXPECT_NEAR(m.shape(5), 0.5, 1e-12);
    EXPECT_NEAR(m.shape(2.5), 0.35, 1e-12);
    EXPECT_DOUBLE_EQ(m.shape(-5), 0.2);   // clamped
    EXPECT_DOUBLE_EQ(m.shape(100), 0.8);  // clamped
}

TEST(FeatureMapping, LogCurveMapsRatiosToRatios) {
    const auto m = make(P::frequency_source, 150, 6000, 50, 320, MappingCurve::log);
    EXPECT_NEAR(m.shape(150), 50, 1e-9);
    EXPECT_NEAR(m.shape(6000), 320, 1e-9);
    EXPECT_NEAR(m.shape(std::sqrt(150.0 * 6000.0)), std::sqrt(50.0 * 320.0), 1e-9);
    // Equal input ratios give equal output ratios.
    const double r = m.shape(400) / m.shape(200);
    EXPECT_NEAR(m.shape(1600) / m.shape(800), r, 1e-9);
    EXPECT_NEAR(r, std::pow(320.0 / 50.0, std::log(2.0) / std::log(40.0)), 1e-9);
    EXPECT_NEAR(m.shape(10), 50, 1e-9);  // clamped
    EXPECT_NEAR(m.shape(0), 50, 1e-9);   // log of 0 stays finite
    EXPECT_NEAR(m.shape(-3), 50, 1e-9);
    EXPECT_NEAR(m.shape(1e6), 320, 1e-9);
}

TEST(FeatureMapping, InputForReadsEveryCurveBackwards) {
    for (const auto curve : {MappingCurve::lin, MappingCurve::log, MappingCurve::exp})
        for (const bool inverted : {false, true}) {
            const auto m = inverted ? make(P::frequency_source, 300, 100, 40, 400, curve)
                                    : make(P::frequency_source, 100, 300, 40, 400, curve);
            for (const double input : {100.0, 137.0, 200.0, 299.0})
                EXPECT_NEAR(m.input_for(m.shape(input)), input, 1e-9) << static_cast<int>(curve);
            EXPECT_NEAR(m.input_for(1), inverted ? 300 : 100, 1e-9);  // beyond the range
            EXPECT_NEAR(m.input_for(1000), inverted ? 100 : 300, 1e-9);
        }
}

TEST(FeatureMapping, ExpCurveMapsDecibelsToAmplitudeRatios) {
    const auto m = make(P::amplitude_source, -60, 0, 0.03, 1, MappingCurve::exp);
    EXPECT_NEAR(m.shape(-60), 0.03, 1e-12);
    EXPECT_NEAR(m.shape(0), 1.0, 1e-12);
    EXPECT_NEAR(m.shape(-30), std::sqrt(0.03), 1e-12);
    // Equal input steps give equal output ratios.
    EXPECT_NEAR(m.shape(-10) / m.shape(-20), m.shape(-40) / m.shape(-50), 1e-12);
    EXPECT_NEAR(m.shape(-100), 0.03, 1e-12);
    EXPECT_NEAR(m.shape(20), 1.0, 1e-12);
}

TEST(FeatureMapping, InvertedRanges) {
    const auto lin = make(P::amplitude_source, 10, 0, 0.2, 0.8, MappingCurve::lin);
    EXPECT_DOUBLE_EQ(lin.shape(10), 0.2);
    EXPECT_DOUBLE_EQ(lin.shape(0), 0.8);
    EXPECT_NEAR(lin.shape(7.5), 0.35, 1e-12);
    EXPECT_DOUBLE_EQ(lin.shape(20), 0.2);
    EXPECT_DOUBLE_EQ(lin.shape(-20), 0.8);

    const auto log = make(P::frequency_source, 6000, 150, 50, 320, MappingCurve::log);
    EXPECT_NEAR(log.shape(6000), 50, 1e-9);
    EXPECT_NEAR(log.shape(150), 320, 1e-9);
    EXPECT_NEAR(log.shape(std::sqrt(150.0 * 6000.0)), std::sqrt(50.0 * 320.0), 1e-9);
    EXPECT_NEAR(log.shape(1e5), 50, 1e-9);
    EXPECT_NEAR(log.shape(1), 320, 1e-9);

    // Inverted output range: decreasing output.
    const auto down = make(P::amplitude_source, -60, 0, 1, 0.03, MappingCurve::exp);
    EXPECT_NEAR(down.shape(-60), 1.0, 1e-12);
    EXPECT_NEAR(down.shape(0), 0.03, 1e-12);
    EXPECT_NEAR(down.shape(-30), std::sqrt(0.03), 1e-12);
}

TEST(FeatureMapping, DegenerateInputRangeGivesOutMin) {
    const auto m = make(P::amplitude_source, 5, 5, 0.2, 0.8, MappingCurve::lin);
    EXPECT_DOUBLE_EQ(m.shape(5), 0.2);
    EXPECT_DOUBLE_EQ(m.shape(0), 0.2);
}

TEST(FeatureMapping, OnePoleSmoothing) {
    // 10 ms at 1000 frames/s: a step gets 1 - 1/e of the way in 10 frames.
    auto m =
        make(P::amplitude_source, 0, 1, 0, 1, MappingCurve::lin, 10.0, FeatureSource::noisiness);
    m.reset(0.0);
    Features f;
    f.noisiness = 1.0;
    double v = 0.0;
    for (int i = 0; i < 10; ++i) v = m.map(f);
    EXPECT_NEAR(v, 1.0 - std::exp(-1.0), 1e-9);
    EXPECT_EQ(m.current(), v);

    auto immediate =
        make(P::amplitude_source, 0, 1, 0, 1, MappingCurve::lin, 0.0, FeatureSource::noisiness);
    EXPECT_DOUBLE_EQ(immediate.map(f), 1.0);
}

TEST(FeatureMapping, ReadsItsSource) {
    Features f;
    f.loudness_db = -20;
    f.brightness_hz = 2000;
    f.noisiness = 0.25;
    f.pitch_hz = 300;
    f.pitch_confidence = 0.5;
    f.onset_odf = 0.75;
    const std::pair<FeatureSource, double> expected[] = {
        {FeatureSource::loudness_db, -20}, {FeatureSource::brightness_hz, 2000},
        {FeatureSource::noisiness, 0.25},  {FeatureSource::tonality, 0.75},
        {FeatureSource::pitch_hz, 300},    {FeatureSource::pitch_confidence, 0.5},
        {FeatureSource::onset_odf, 0.75}};
    for (const auto& [source, value] : expected) {
        auto m = make(P::square_mix_source, -1e6, 1e6, 0, 1, MappingCurve::lin, 0, source);
        EXPECT_NEAR(m.map(f), (value + 1e6) / 2e6, 1e-12) << static_cast<int>(source);
        EXPECT_EQ(feature_value(f, source), value);
    }
}

}  // namespace
}  // namespace tactus
