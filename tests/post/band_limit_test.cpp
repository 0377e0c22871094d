// BandLimit: Butterworth high-pass + low-pass pairs. Gain at DC, -3.01 dB at both corners for
// every order, flat mid-band, near Nyquist; the designed response against the bilinear closed
// form; the measured response of process() (sines) against magnitude_db(); at 44.1 and 192 kHz.
#include "tactus/post/band_limit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "support/signals.hpp"

namespace tactus {
namespace {

using test::kCornerDb;

// |H|^2 of an order-n bilinear Butterworth pair pre-warped at its corners, in dB.
double closed_form_db(double f, double low, double high, int order, double fs) {
    const double t = std::tan(kPi * f / fs);
    const double rh = t / std::tan(kPi * low / fs), rl = t / std::tan(kPi * high / fs);
    return -10.0 * std::log10(1.0 + std::pow(rh, -2 * order)) -
           10.0 * std::log10(1.0 + std::pow(rl, 2 * order));
}

struct BandLimitSetting {
    double fs;
    int order;
};

class BandLimitCase : public ::testing::TestWithParam<BandLimitSetting> {};

TEST_P(BandLimitCase, DesignedResponse) {
    const auto [fs, order] = GetParam();
    BandLimit band;
    band.prepare({.sample_rate_hz = fs}, {.low_hz = 20.0, .high_hz = 1000.0, .order = order});
    // The far corner contributes (20/1000)^(2n) ~ 1e-7 dB: each corner reads the Butterworth -3.01.
    EXPECT_NEAR(band.magnitude_db(20.0), kCornerDb, 0.001);
    EXPECT_NEAR(band.magnitude_db(1000.0), kCornerDb, 0.001);
    EXPECT_NEAR(band.magnitude_db(std::sqrt(20.0 * 1000.0)), 0.0, 0.01);
    EXPECT_LT(band.magnitude_db(0.0), -200.0);
    EXPECT_LT(band.magnitude_db(0.49 * fs), -60.0 * order / 2);
    for (double f = 5.0; f < 0.45 * fs; f *= 1.19)
        EXPECT_NEAR(band.magnitude_db(f), closed_form_db(f, 20.0, 1000.0, order, fs), 1e-6)
            << f << " Hz";
}

TEST_P(BandLimitCase, MeasuredResponseMatchesDesign) {
    const auto [fs, order] = GetParam();
    for (double f : {20.0, 31.0, 141.4, 1000.0, 1500.0, 2000.0}) {
        BandLimit band;
        band.prepare({.sample_rate_hz = fs}, {.low_hz = 20.0, .high_hz = 1000.0, .order = order});
        const double measured =
            test::measured_gain_db([&](float* x, int n) { band.process(x, n); }, f, fs);
        EXPECT_NEAR(measured, band.magnitude_db(f), 0.02) << f << " Hz at " << fs << " Hz";
    }
}

INSTANTIATE_TEST_SUITE_P(RatesAndOrders, BandLimitCase,
                         ::testing::Values(BandLimitSetting{44100, 2}, BandLimitSetting{44100, 4},
                                           BandLimitSetting{44100, 8}, BandLimitSetting{192000, 2},
                                           BandLimitSetting{192000, 4}, BandLimitSetting{8000, 2}));

TEST(BandLimit, NoLowpassAtOrAboveFortyFivePercentOfTheRate) {
    BandLimit band;
    band.prepare({.sample_rate_hz = 8000.0},
                 {.low_hz = 20.0,
                  .high_hz = 3700.0,
                  .order = 2});  // 3700 >= 0.45 * 8000: the band ends at Nyquist
    EXPECT_NEAR(band.magnitude_db(3700.0), 0.0, 0.001);
    EXPECT_NEAR(band.magnitude_db(3999.0), 0.0, 0.001);
    EXPECT_NEAR(band.magnitude_db(20.0), kCornerDb, 0.001);
}

TEST(BandLimit, HighPassAloneLeavesTheTopOpen) {
    BandLimit band;
    band.prepare({.sample_rate_hz = 44100.0},
                 {.low_hz = 30.0, .high_hz = 1000.0, .order = 8, .low_pass = false});
    EXPECT_NEAR(band.magnitude_db(30.0), kCornerDb, 0.001);
    EXPECT_NEAR(band.magnitude_db(1000.0), 0.0, 0.001);
    EXPECT_NEAR(band.magnitude_db(10000.0), 0.0, 0.001);
    const double measured =
        test::measured_gain_db([&](float* x, int n) { band.process(x, n); }, 2000.0, 44100.0);
    EXPECT_NEAR(measured, 0.0, 0.02);
}

TEST(BandLimit, RejectsInvalidOrders) {
    BandLimit band;
    for (int order : {0, 1, 3, 10, -2})
        EXPECT_THROW(band.prepare({.sample_rate_hz = 48000.0},
                                  {.low_hz = 20.0, .high_hz = 1000.0, .order = order}),
                     std::invalid_argument)
            << order;
    EXPECT_NO_THROW(
        band.prepare({.sample_rate_hz = 48000.0},
                     {.low_hz = 20.0, .high_hz = 1000.0, .order = BandLimit::kMaxOrder}));
}

TEST(BandLimit, ResetGivesTheSameOutputAgain) {
    BandLimit band;
    band.prepare({.sample_rate_hz = 48000.0}, {.low_hz = 20.0, .high_hz = 1000.0, .order = 4});
    std::vector<float> a = test::white_noise(4096, 7), b = a;
    band.process(a.data(), static_cast<int>(a.size()));
    band.reset();
    band.process(b.data(), static_cast<int>(b.size()));
    EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace tactus
