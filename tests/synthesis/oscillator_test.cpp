// Oscillator: at mix 0 a pure sine (one spectral peak, everything else < -80 dB); at mix 1 the
// odd harmonics have amplitude 4/(pi k) up to the fade region below the harmonic limit, even
// harmonics are absent, and there is nothing (< -80 dB re the fundamental) above the limit nor
// aliased below the fundamental; at several f0 (some not dividing the rate) at 8 and 48 kHz.
// Also: the mix is linear, the limit is clamped to 0.45 fs, the square's fundamental keeps its
// level at every f0 (also above the limit), and a non-finite frequency neither hangs next() nor
// poisons later output.
#include "tactus/synthesis/oscillator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/signals.hpp"
#include "support/watchdog.hpp"
#include "tactus/core/units.hpp"

namespace tactus {
namespace {

constexpr size_t kLength = 1 << 16;
constexpr double kFloor = 1e-4;  // -80 dB

std::vector<double> render(double fs, double limit_hz, double f0, double mix) {
    Oscillator osc;
    osc.prepare({.sample_rate_hz = fs}, limit_hz);
    std::vector<double> x(kLength);
    for (auto& v : x) v = osc.next(f0, mix);
    return x;
}

double db(double ratio) {
    return 20.0 * std::log10(ratio);
}

struct OscillatorSetting {
    double fs, limit_hz, f0;
};

class OscillatorCase : public ::testing::TestWithParam<OscillatorSetting> {};

TEST_P(OscillatorCase, SineHasASingleSpectralPeak) {
    const auto [fs, limit, f0] = GetParam();
    const auto x = render(fs, limit, f0, 0.0);
    const test::Spectrum s(x, fs);
    const double guard = 8 * s.bin_hz();
    EXPECT_NEAR(db(s.amplitude_near(f0)), 0.0, 0.01);
    EXPECT_LT(s.max_bin_amplitude(0.0, f0 - guard), kFloor) << "below f0 " << f0;
    EXPECT_LT(s.max_bin_amplitude(f0 + guard, fs / 2), kFloor) << "above f0 " << f0;
}

TEST_P(OscillatorCase, SquareHarmonicsFollowOneOverKBelowTheLimit) {
    const auto [fs, limit_hz, f0] = GetParam();
    const double limit = std::min(limit_hz, 0.45 * fs);
    const auto x = render(fs, limit_hz, f0, 1.0);
    const test::Spectrum s(x, fs);
    const double fundamental = s.amplitude_near(f0);
    int full = 0;
    for (int k = 1; k * f0 < limit; k += 2) {
        const double expected = 4.0 / (kPi * k);
        const double measured = s.amplitude_near(k * f0);
        if (k * f0 <= limit - 2 * f0) {  // below the fade: exactly the square's series
            EXPECT_NEAR(db(measured / expected), 0.0, 0.05) << "harmonic " << k << " of " << f0;
            ++full;
        } else {  // the top harmonic(s) fade out towards the limit
            EXPECT_LE(measured, expected * 1.006) << "harmonic " << k << " of " << f0;
        }
        if ((k + 1) * f0 < fs / 2) {
            EXPECT_LT(s.amplitude_near((k + 1) * f0), kFloor * fundamental)
                << "even harmonic " << k + 1 << " of " << f0;
        }
    }
    EXPECT_GE(full, 1);
    const double guard = 8 * s.bin_hz();
    EXPECT_LT(s.max_bin_amplitude(limit + guard, fs / 2), kFloor * fundamental)
        << "energy above the " << limit << " Hz limit, f0 " << f0;
    EXPECT_LT(s.max_bin_amplitude(0.0, f0 - guard), kFloor * fundamental)
        << "aliased energy below f0 " << f0;
}

INSTANTIATE_TEST_SUITE_P(
    RatesAndPitches, OscillatorCase,
    ::testing::Values(OscillatorSetting{48000, 1000, 23.7}, OscillatorSetting{48000, 1000, 50},
                      OscillatorSetting{48000, 1000, 73.3}, OscillatorSetting{48000, 1000, 101.7},
                      OscillatorSetting{48000, 1000, 237.1}, OscillatorSetting{48000, 1000, 320},
                      OscillatorSetting{48000, 2000, 61.9}, OscillatorSetting{8000, 1000, 55.5},
                      OscillatorSetting{8000, 1000, 123.4}, OscillatorSetting{8000, 1000, 300},
                      OscillatorSetting{8000, 4000, 97.3}, OscillatorSetting{8000, 4000, 440}));

TEST(Oscillator, MixIsLinearBetweenSineAndSquare) {
    const double fs = 48000, f0 = 87.3;
    Oscillator sine, square, half;
    sine.prepare({.sample_rate_hz = fs}, 1000);
    square.prepare({.sample_rate_hz = fs}, 1000);
    half.prepare({.sample_rate_hz = fs}, 1000);
    for (int i = 0; i < 10000; ++i) {
        const double a = sine.next(f0, 0.0), b = square.next(f0, 1.0), c = half.next(f0, 0.25);
        ASSERT_NEAR(c, 0.75 * a + 0.25 * b, 1e-12) << i;
    }
}

TEST(Oscillator, RestartPhaseStartsAtAZeroCrossing) {
    Oscillator osc;
    osc.prepare({.sample_rate_hz = 48000}, 1000);
    for (int i = 0; i < 1234; ++i) osc.next(100.0, 0.5);
    osc.reset();
    EXPECT_EQ(osc.next(100.0, 1.0), 0.0);
    EXPECT_GT(osc.next(100.0, 1.0), 0.0);
}

// The fundamental needs no fading: below the limit it is part of the band-limited square, and
// above it the square has nothing else left. At mix 1 its level must stay 4/pi whatever f0
// (fading it makes mix 1 quieter than mix 0, down to silence). f0 above the limit happens when
// mapping.frequency.out_max exceeds post.band_high_hz.
TEST(Oscillator, SquareFundamentalIsNeverFaded) {
    const double fs = 48000;
    for (double f0 : {400.0, 600.0, 900.0, 999.0, 1200.0, 2000.0}) {
        const auto x = render(fs, 1000, f0, 1.0);
        const test::Spectrum s(x, fs);
        EXPECT_NEAR(db(s.amplitude_near(f0) / (4.0 / kPi)), 0.0, 0.05) << "f0 " << f0;
    }
}

// A NaN or infinite frequency (e.g. from a NaN feature) must not hang the audio thread.
TEST(Oscillator, NonFiniteFrequencyReturns) {
    TACTUS_EXPECT_FINISHES_OK(5, []() -> std::string {
        Oscillator osc;
        osc.prepare({.sample_rate_hz = 48000}, 1000);
        for (double f :
             {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
            for (double mix : {0.0, 0.5, 1.0}) osc.next(f, mix);
        return "";
    });
}

// One bad frequency must not poison the phase: the next finite frequency gives finite output.
TEST(Oscillator, NonFiniteFrequencyDoesNotPoisonLaterOutput) {
    for (double bad :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        Oscillator osc;
        osc.prepare({.sample_rate_hz = 48000}, 1000);
        osc.next(bad, 1.0);
        for (int i = 0; i < 100; ++i) ASSERT_TRUE(std::isfinite(osc.next(100.0, 0.5))) << bad;
    }
}

// Under limit / 1024 the series keeps its 512 tabled odd harmonics: up to 1021 f0 at 4/(pi k),
// 1023 f0 at half that, nothing above.
TEST(Oscillator, SquareUnderAThousandthOfTheLimitKeepsItsTabledHarmonics) {
    const double fs = 4000, f0 = 0.7;  // 1023 f0 = 716 Hz, under the 1 kHz limit
    const auto x = render(fs, 1000, f0, 1.0);
    const test::Spectrum s(x, fs);
    for (int k : {3, 101, 1021})
        EXPECT_NEAR(db(s.amplitude_near(k * f0) / (4.0 / (kPi * k))), 0.0, 0.1) << k;
    EXPECT_NEAR(db(s.amplitude_near(1023 * f0) / (2.0 / (kPi * 1023))), 0.0, 0.1);
    EXPECT_LT(s.max_bin_amplitude(1023 * f0 + 0.5 * f0, fs / 2), kFloor * s.amplitude_near(f0));
}

TEST(Oscillator, HarmonicLimitIsClampedBelowNyquist) {
    const double fs = 8000, f0 = 410.0;
    const auto x = render(fs, 5000, f0, 1.0);  // asks for 5 kHz; gets 0.45 fs = 3600 Hz
    const test::Spectrum s(x, fs);
    const double fundamental = s.amplitude_near(f0);
    EXPECT_LT(s.max_bin_amplitude(3600 + 8 * s.bin_hz(), fs / 2), kFloor * fundamental);
    EXPECT_LT(s.max_bin_amplitude(0, f0 - 8 * s.bin_hz()), kFloor * fundamental);
    EXPECT_NEAR(db(s.amplitude_near(3 * f0) / (4.0 / (3 * kPi))), 0.0, 0.05);
}

}  // namespace
}  // namespace tactus
