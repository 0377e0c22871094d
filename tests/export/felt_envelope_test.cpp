// The felt envelope against closed forms: a steady sine reads its amplitude weighted by the P
// channel's sensitivity at its frequency (0 dB at 250 Hz, the threshold curve's difference
// elsewhere), at every step, whatever the phase.
#include "tactus/export/felt_envelope.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tactus/perception/threshold.hpp"

namespace tactus {
namespace {

std::vector<double> felt_of_sine(double frequency_hz, double amplitude, double seconds) {
    constexpr double kRateHz = 48000;
    FeltEnvelope envelope(kRateHz);
    std::vector<float> sine(static_cast<size_t>(seconds * kRateHz));
    for (size_t i = 0; i < sine.size(); ++i)
        sine[i] = static_cast<float>(amplitude *
                                     std::sin(2 * std::numbers::pi * frequency_hz * i / kRateHz));
    envelope.write(sine.data(), static_cast<int>(sine.size()), frequency_hz);
    return envelope.felt();
}

TEST(FeltEnvelope, SineReadsItsAmplitudeWeightedByThePThreshold) {
    for (const double f : {40.0, 80.0, 250.0, 400.0}) {
        const double expected =
            0.5 *
            std::pow(10.0, (perception::p_threshold_db(250) - perception::p_threshold_db(f)) / 20);
        const std::vector<double> felt = felt_of_sine(f, 0.5, 0.5);
        ASSERT_EQ(felt.size(), 500u);
        for (size_t i = 0; i < felt.size(); ++i)
            ASSERT_NEAR(felt[i], expected, 0.01 * expected) << f << " Hz, step " << i;
    }
    EXPECT_DOUBLE_EQ(FeltEnvelope::weight(250), 1.0);
    // The curve 28 dB higher at 40 Hz than at 250 Hz: what the flattening filter boosts back.
    EXPECT_NEAR(20 * std::log10(FeltEnvelope::weight(40)), -28.2, 0.1);
}

TEST(FeltEnvelope, SilenceIsZeroAndABurstEndsWithinACarrierPeriod) {
    constexpr double kRateHz = 48000;
    FeltEnvelope envelope(kRateHz);
    std::vector<float> signal(static_cast<size_t>(0.2 * kRateHz), 0.0f);
    for (size_t i = 0; i < signal.size() / 2; ++i)
        signal[i] = static_cast<float>(std::sin(2 * std::numbers::pi * 250 * i / kRateHz));
    envelope.write(signal.data(), static_cast<int>(signal.size()), 250);
    const std::vector<double> felt = envelope.felt();
    EXPECT_NEAR(felt[50], 1.0, 0.01);
    EXPECT_EQ(felt[100 + 3], 0.0);  // 2 ms (half a period) after the burst
    EXPECT_EQ(felt.back(), 0.0);
}

}  // namespace
}  // namespace tactus
