// Export normalisation against hand-worked tracks: peak keeps the rendered scale, pNN puts the
// NN-th percentile of the hits (linear between ranks, as numpy.percentile) at 1 and clips above,
// a gain scales after it, a track without hits falls back to its peak, and every bad name is
// refused with a line that quotes it.
#include "tactus/export/normalisation.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace tactus {
namespace {

// Hits at 0.2, 0.4, 0.6, 0.8, 1.0 (a rendered track: its peak is 1), envelope through them.
HapticTrack five_hits() {
    HapticTrack track;
    track.intensity = {0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 0.1};
    for (const double v : {0.2, 0.4, 0.6, 0.8, 1.0}) track.onsets.push_back({.intensity = v});
    track.felt_full_scale = 0.5;
    return track;
}

TEST(Normalisation, PeakKeepsTheRenderedScale) {
    HapticTrack track = five_hits();
    normalise(track, Normalisation::parse("peak"));
    EXPECT_EQ(track.intensity, five_hits().intensity);
    EXPECT_DOUBLE_EQ(track.felt_full_scale, 0.5);
    EXPECT_NE(track.normalisation.find("the peak is full scale, gain +0.0 dB"), std::string::npos)
        << track.normalisation;
}

TEST(Normalisation, PercentileOfTheHitsBecomesFullScaleAndLouderClips) {
    HapticTrack track = five_hits();
    normalise(track, Normalisation::parse("p50"));  // the median hit, 0.6
    const std::vector<double> expected = {0.0, 0.2 / 0.6, 0.4 / 0.6, 1.0, 1.0, 1.0, 0.1 / 0.6};
    for (size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(track.intensity[i], expected[i], 1e-12) << i;
    EXPECT_NEAR(track.onsets[0].intensity, 0.2 / 0.6, 1e-12);
    EXPECT_EQ(track.onsets[4].intensity, 1.0);
    EXPECT_NEAR(track.felt_full_scale, 0.5 * 0.6, 1e-12);  // the felt amplitude now at 1
    EXPECT_NE(track.normalisation.find("p50 of the hits' felt peaks (5 hits; 0.600 of the peak)"),
              std::string::npos)
        << track.normalisation;
    EXPECT_NE(track.normalisation.find("28.6 % of the time clipped"), std::string::npos)
        << track.normalisation;  // 2 of 7 steps
    // Between ranks: p90 of five is 0.8 + 0.6 * (1.0 - 0.8).
    track = five_hits();
    normalise(track, Normalisation::parse("p90"));
    EXPECT_NEAR(track.intensity[4], 0.8 / 0.92, 1e-12);
}

TEST(Normalisation, GainScalesAfterTheReference) {
    HapticTrack track = five_hits();
    normalise(track, Normalisation::parse("p50", -6.0));
    EXPECT_NEAR(track.intensity[3], std::pow(10.0, -6.0 / 20), 1e-12);
    EXPECT_NE(track.normalisation.find("gain -6.0 dB"), std::string::npos) << track.normalisation;
}

TEST(Normalisation, WithoutHitsThePeakIsFullScale) {
    HapticTrack track = five_hits();
    track.onsets.clear();
    normalise(track, Normalisation{});
    EXPECT_EQ(track.intensity, five_hits().intensity);
    EXPECT_NE(track.normalisation.find("the peak (no hits for p99)"), std::string::npos)
        << track.normalisation;
}

TEST(Normalisation, NamesAreParsedStrictly) {
    EXPECT_EQ(Normalisation{}.name(), "p99");
    EXPECT_EQ(Normalisation::parse("p99.5").name(), "p99.5");
    EXPECT_EQ(Normalisation::parse("p100").percentile, 100);
    for (const char* bad : {"", "p", "p49", "p101", "p9x", "P99", "peak ", "99", "pnan", "p-1"}) {
        try {
            Normalisation::parse(bad);
            ADD_FAILURE() << "'" << bad << "' accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(
                std::string(e.what()).find(std::string("'") + bad + "': expected peak or pNN"),
                std::string::npos)
                << e.what();
        }
    }
    EXPECT_THROW(Normalisation::parse("peak", 41), std::invalid_argument);
    EXPECT_THROW(Normalisation::parse("peak", NAN), std::invalid_argument);
}

}  // namespace
}  // namespace tactus
