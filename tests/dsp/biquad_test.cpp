// Biquad designs and the filter itself: closed-form gains of the cookbook low-pass, high-pass,
// peaking and shelving designs (DC, corner, near Nyquist) at 44.1, 48 and 192 kHz, the
// Butterworth Q table, and the measured response of process() against magnitude_db().
#include "tactus/dsp/biquad.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/signals.hpp"

namespace tactus {
namespace {

using test::kCornerDb;
constexpr double kButterworthQ = 0.70710678118654752;

class BiquadAtRate : public ::testing::TestWithParam<double> {};

TEST_P(BiquadAtRate, LowpassDcCornerAndNyquist) {
    const double fs = GetParam();
    for (double fc : {50.0, 1000.0, 5000.0}) {
        const auto c = BiquadCoefficients::lowpass(fc, kButterworthQ, fs);
        EXPECT_NEAR(c.magnitude_db(0.0, fs), 0.0, 1e-9) << "fc " << fc;
        EXPECT_NEAR(c.magnitude_db(fc, fs), kCornerDb, 1e-6) << "fc " << fc;
        // Second order: -12 dB/octave far above the corner; zeros at Nyquist.
        EXPECT_LT(c.magnitude_db(0.49 * fs, fs), -40.0) << "fc " << fc;
        EXPECT_LT(c.magnitude_db(0.5 * fs, fs), -200.0) << "fc " << fc;
    }
}

TEST_P(BiquadAtRate, HighpassDcCornerAndNyquist) {
    const double fs = GetParam();
    for (double fc : {20.0, 200.0, 2000.0}) {
        const auto c = BiquadCoefficients::highpass(fc, kButterworthQ, fs);
        EXPECT_LT(c.magnitude_db(0.0, fs), -200.0) << "fc " << fc;
        EXPECT_NEAR(c.magnitude_db(fc, fs), kCornerDb, 1e-6) << "fc " << fc;
        EXPECT_NEAR(c.magnitude_db(0.5 * fs, fs), 0.0, 1e-6) << "fc " << fc;
        EXPECT_NEAR(c.magnitude_db(0.45 * fs, fs), 0.0, 0.01) << "fc " << fc;
    }
}

TEST_P(BiquadAtRate, ButterworthMatchesBilinearClosedForm) {
    // A bilinear-transform Butterworth pre-warped at the corner has
    //   |H(f)|^2 = 1 / (1 + (tan(pi f/fs) / tan(pi fc/fs))^4)  (low-pass, order 2).
    const double fs = GetParam(), fc = 700.0;
    const auto low = BiquadCoefficients::lowpass(fc, kButterworthQ, fs);
    const auto high = BiquadCoefficients::highpass(fc, kButterworthQ, fs);
    for (double f = 10.0; f < 0.45 * fs; f *= 1.37) {
        const double r = std::tan(kPi * f / fs) / std::tan(kPi * fc / fs);
        EXPECT_NEAR(low.magnitude_db(f, fs), -10.0 * std::log10(1.0 + std::pow(r, 4)), 1e-6)
            << f << " Hz";
        EXPECT_NEAR(high.magnitude_db(f, fs), -10.0 * std::log10(1.0 + std::pow(r, -4)), 1e-6)
            << f << " Hz";
    }
}

TEST_P(BiquadAtRate, PeakingAndShelves) {
    const double fs = GetParam();
    for (double gain_db : {-24.0, -6.0, 9.0}) {
        const auto peak = BiquadCoefficients::peaking(250.0, 1.41, gain_db, fs);
        EXPECT_NEAR(peak.magnitude_db(250.0, fs), gain_db, 1e-6);
        EXPECT_NEAR(peak.magnitude_db(0.0, fs), 0.0, 1e-9);
        EXPECT_NEAR(peak.magnitude_db(0.5 * fs, fs), 0.0, 1e-6);

        const auto low = BiquadCoefficients::low_shelf(300.0, gain_db, fs);
        EXPECT_NEAR(low.magnitude_db(0.0, fs), gain_db, 1e-6);
        EXPECT_NEAR(low.magnitude_db(300.0, fs), gain_db / 2, 1e-6);  // half gain at the corner
        EXPECT_NEAR(low.magnitude_db(0.5 * fs, fs), 0.0, 1e-6);

        const auto high = BiquadCoefficients::high_shelf(3000.0, gain_db, fs);
        EXPECT_NEAR(high.magnitude_db(0.0, fs), 0.0, 1e-9);
        EXPECT_NEAR(high.magnitude_db(3000.0, fs), gain_db / 2, 1e-6);
        EXPECT_NEAR(high.magnitude_db(0.5 * fs, fs), gain_db, 1e-6);
    }
}

TEST_P(BiquadAtRate, ProcessMatchesDesignedResponse) {
    const double fs = GetParam();
    const auto designs = {BiquadCoefficients::lowpass(1000.0, kButterworthQ, fs),
                          BiquadCoefficients::highpass(40.0, kButterworthQ, fs),
                          BiquadCoefficients::peaking(250.0, 1.41, -12.0, fs)};
    for (const auto& c : designs) {
        for (double f : {25.0, 40.0, 250.0, 1000.0, 2000.0}) {
            Biquad biquad;
            biquad.set(c);
            const double measured = test::measured_gain_db(
                [&](float* x, int n) {
                    for (int i = 0; i < n; ++i) x[i] = static_cast<float>(biquad.process(x[i]));
                },
                f, fs);
            EXPECT_NEAR(measured, c.magnitude_db(f, fs), 0.02) << f << " Hz at " << fs;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Rates, BiquadAtRate, ::testing::Values(44100.0, 48000.0, 192000.0));

TEST(Biquad, ButterworthQTable) {
    EXPECT_NEAR(butterworth_q(2, 0), 0.7071067812, 1e-9);
    EXPECT_NEAR(butterworth_q(4, 0), 0.5411961001, 1e-9);
    EXPECT_NEAR(butterworth_q(4, 1), 1.3065629649, 1e-9);
    EXPECT_NEAR(butterworth_q(8, 3), 2.5629154477, 1e-9);
}

TEST(Biquad, DefaultIsIdentityAndResetClearsState) {
    Biquad identity;
    for (double x : {1.0, -0.5, 0.25}) EXPECT_EQ(identity.process(x), x);

    Biquad lowpass;
    lowpass.set(BiquadCoefficients::lowpass(100.0, kButterworthQ, 48000.0));
    const double first = lowpass.process(1.0);
    for (int i = 0; i < 10; ++i) lowpass.process(1.0);
    lowpass.reset();
    EXPECT_EQ(lowpass.process(1.0), first);
    EXPECT_EQ(lowpass.coefficients().b0, first);
}

}  // namespace
}  // namespace tactus
