// A hit's part features (analysis/part_features.hpp): the own numbers say where its added power
// lies, and the relative ones read it against the song's recent hits, so a snare that sits low
// reads low only against a higher kit, and high against its own kick.
#include "tactus/analysis/part_features.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tactus {
namespace {

constexpr SpectrumShape kShape{.bins = 81, .bin_hz = 100};  // 0-8 kHz
constexpr size_t kOwn = PartFeatures::kOwn;
constexpr size_t kLowShare = PartFeatures::kFineBands;  // the share below 150 Hz

// A hit adding `low` below 150 Hz and `mid` spread over 200 Hz-4 kHz (power).
std::vector<float> computed(PartFeatures& features, double low, double mid) {
    std::vector<float> spectrum(kShape.bins, 0.0f), bed(kShape.bins, 1e-6f);
    for (int k = 2; k <= 40; ++k) spectrum[static_cast<size_t>(k)] = static_cast<float>(mid / 39);
    EXPECT_TRUE(features.compute(
        {.fast = spectrum, .fine = spectrum, .fine_bed = bed, .low = low, .high = 1e-3}));
    const auto values = features.values();
    return {values.begin(), values.end()};
}

TEST(PartFeatures, TheFirstHitIsItsOwnRecentMean) {
    PartFeatures features;
    features.prepare(kShape, kShape);
    const std::vector<float> first = computed(features, 1, 1);
    for (size_t i = 0; i < kOwn; ++i) EXPECT_EQ(first[kOwn + i], 0.0f) << i;
    const std::vector<float> again = computed(features, 1, 1);
    for (size_t i = 0; i < kOwn; ++i) EXPECT_FLOAT_EQ(again[kOwn + i], 0.0f) << i;
}

TEST(PartFeatures, AHitReadsAgainstTheRecentHits) {
    PartFeatures features;
    features.prepare(kShape, kShape);
    // A kit whose kick and snare both add most below 150 Hz, the snare a little less.
    const double snare_low = 2, kick_low = 20;
    const std::vector<float> snare_alone = computed(features, snare_low, 1);
    EXPECT_GT(snare_alone[kLowShare], -0.3f);  // two thirds of it below 150 Hz
    const int kicks = 8;
    float kick_share = 0;
    for (int i = 0; i < kicks; ++i) kick_share = computed(features, kick_low, 1)[kLowShare];
    const std::vector<float> snare = computed(features, snare_low, 1);
    EXPECT_EQ(snare[kLowShare], snare_alone[kLowShare]);
    // Against its kick: the recent mean has moved all but (1 - 1/kRecentHits)^8 of the way from
    // the snare's share to the kick's.
    const double moved = 1 - std::pow(1 - 1 / PartFeatures::kRecentHits, kicks);
    EXPECT_LT(snare[kOwn + kLowShare], -0.1f);
    EXPECT_NEAR(snare[kOwn + kLowShare], moved * (snare_alone[kLowShare] - kick_share), 1e-5);
    // A new song forgets the kick.
    features.reset();
    EXPECT_EQ(computed(features, snare_low, 1)[kOwn + kLowShare], 0.0f);
}

}  // namespace
}  // namespace tactus
