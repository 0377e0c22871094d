// Loudness (K-weighted, short window): a full-scale 997 Hz sine reads -3.01 dB (+-0.2) at
// several rates and windows, doubling the amplitude adds 6.02 dB (+-0.05), silence reads the
// floor, and the frequency weighting matches the BS.1770-4 48 kHz filter coefficients.
#include "tactus/analysis/loudness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "support/signals.hpp"

namespace tactus {
namespace {

double loudness_of(const std::vector<float>& x, double fs, double window_ms) {
    Loudness loudness;
    loudness.prepare({.sample_rate_hz = fs}, window_ms);
    loudness.process(x.data(), static_cast<int>(x.size()));
    return loudness.loudness_db();
}

TEST(Loudness, FullScale997HzSineReadsMinus3Db) {
    for (double fs : {8000.0, 44100.0, 48000.0, 96000.0, 192000.0}) {
        for (double window_ms : {10.0, 100.0, 400.0}) {
            const auto x = test::sine(997.0, fs, static_cast<size_t>(fs), 1.0);
            EXPECT_NEAR(loudness_of(x, fs, window_ms), -3.01, 0.2)
                << fs << " Hz, window " << window_ms << " ms";
        }
    }
}

TEST(Loudness, DoublingAmplitudeAddsSixDb) {
    for (double fs : {44100.0, 48000.0}) {
        for (double a : {0.001, 0.05, 0.25}) {
            const auto x = test::sine(997.0, fs, static_cast<size_t>(fs / 2), a);
            const auto y = test::sine(997.0, fs, static_cast<size_t>(fs / 2), 2 * a);
            EXPECT_NEAR(loudness_of(y, fs, 10) - loudness_of(x, fs, 10), 6.0206, 0.05)
                << "amplitude " << a << " at " << fs;
        }
    }
}

TEST(Loudness, SilenceReadsTheFloor) {
    const std::vector<float> x(48000, 0.0f);
    EXPECT_EQ(loudness_of(x, 48000, 10), Loudness::kFloorDb);
    Loudness fresh;
    fresh.prepare({.sample_rate_hz = 48000}, 10);
    EXPECT_EQ(fresh.loudness_db(), Loudness::kFloorDb);
    // A sound followed by a full window of silence reads the floor again.
    auto y = test::sine(997.0, 48000, 48000, 0.5);
    y.resize(y.size() + 24000, 0.0f);  // 0.5 s: the K filter rings for a while
    EXPECT_EQ(loudness_of(y, 48000, 10), Loudness::kFloorDb);
}

// The BS.1770-4 K-weighting published for 48 kHz (pre-filter then RLB high-pass).
double standard_k_weighting_db(double f) {
    const std::complex<double> z1 = std::polar(1.0, -2.0 * kPi * f / 48000.0), z2 = z1 * z1;
    const auto shelf = (1.53512485958697 - 2.69169618940638 * z1 + 1.19839281085285 * z2) /
                       (1.0 - 1.69065929318241 * z1 + 0.73248077421585 * z2);
    const auto highpass =
        (1.0 - 2.0 * z1 + 1.0 * z2) / (1.0 - 1.99004745483398 * z1 + 0.99007225036621 * z2);
    return 20.0 * std::log10(std::abs(shelf * highpass));
}

TEST(Loudness, FrequencyWeightingIsBs1770) {
    const double fs = 48000;
    const double reference = loudness_of(test::sine(997.0, fs, 48000, 0.5), fs, 400);
    for (double f : {40.0, 100.0, 500.0, 2000.0, 5000.0, 10000.0, 16000.0}) {
        const double level = loudness_of(test::sine(f, fs, 48000, 0.5), fs, 400);
        EXPECT_NEAR(level - reference, standard_k_weighting_db(f) - standard_k_weighting_db(997.0),
                    0.05)
            << f << " Hz";
    }
}

}  // namespace
}  // namespace tactus
