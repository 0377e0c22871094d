// PeakLimiter: the output never exceeds the ceiling whatever the input (noise at +40 dB,
// full-scale squares, impulses, DC steps), for several settings; non-finite input behaves as 0
// and never gives non-finite output; a signal below the threshold passes bit-exactly, delayed
// by latency(); louder input stays louder; curve() is the documented soft knee and is
// strictly increasing (never reaching the ceiling) up to full scale at the largest drive.
#include "tactus/post/peak_limiter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "support/signals.hpp"
#include "tactus/core/units.hpp"

namespace tactus {
namespace {

struct LimiterSettings {
    double fs, lookahead_ms, release_ms, drive_db, threshold_db, ceiling;
};

std::string describe(const LimiterSettings& s) {
    return "fs " + std::to_string(s.fs) + ", lookahead " + std::to_string(s.lookahead_ms) +
           " ms, release " + std::to_string(s.release_ms) + " ms, drive " +
           std::to_string(s.drive_db) + " dB, threshold " + std::to_string(s.threshold_db) +
           " dB, ceiling " + std::to_string(s.ceiling);
}

PeakLimiter make(const LimiterSettings& s) {
    PeakLimiter limiter;
    limiter.prepare({.sample_rate_hz = s.fs}, s.lookahead_ms,
                    {.drive_db = s.drive_db,
                     .threshold_db = s.threshold_db,
                     .ceiling = s.ceiling,
                     .release_ms = s.release_ms});
    return limiter;
}

// Hostile inputs, each a few seconds long at fs.
std::vector<std::pair<std::string, std::vector<float>>> hostile_inputs(double fs) {
    std::vector<std::pair<std::string, std::vector<float>>> inputs;
    const auto n = static_cast<size_t>(2 * fs);
    inputs.emplace_back("noise +40 dB", test::white_noise(n, 11, 100.0));
    inputs.emplace_back("noise 0 dB", test::white_noise(n, 12, 1.0));
    for (double f : {37.0, 100.0, 333.0, 1000.0}) {
        std::vector<float> square(n);
        for (size_t i = 0; i < n; ++i)
            square[i] = std::fmod(double(i) * f / fs, 1.0) < 0.5 ? 1.0f : -1.0f;
        inputs.emplace_back("square " + std::to_string(f) + " Hz", square);
    }
    std::vector<float> impulses(n, 0.0f);
    for (size_t i = 100, k = 0; i < n; i += 997 + 37 * (k % 5), ++k)
        impulses[i] = (k % 2 ? -1.0f : 1.0f) * (k % 3 == 0 ? 1000.0f : 1.0f);
    inputs.emplace_back("impulses", impulses);
    std::vector<float> steps(n, 0.0f);
    const float levels[] = {0.0f, 1.0f, -1.0f, 10.0f, 0.3f, -10.0f, 0.0f, 4.0f};
    for (size_t i = 0; i < n; ++i) steps[i] = levels[(i * 8) / n];
    inputs.emplace_back("DC steps", steps);
    std::vector<float> bursts = test::sine(80.0, fs, n, 3.0);
    for (size_t i = 0; i < n; ++i)
        if ((i / static_cast<size_t>(0.05 * fs)) % 3 != 0) bursts[i] = 0.0f;
    inputs.emplace_back("80 Hz bursts at +9.5 dB", bursts);
    return inputs;
}

class LimiterSettingsCase : public ::testing::TestWithParam<LimiterSettings> {};

TEST_P(LimiterSettingsCase, NeverAboveTheCeiling) {
    const LimiterSettings s = GetParam();
    for (auto& [name, input] : hostile_inputs(s.fs)) {
        PeakLimiter limiter = make(s);
        std::vector<float> y = input;
        // Odd block sizes: the bound must not depend on them.
        for (size_t done = 0; done < y.size();) {
            const int count = static_cast<int>(std::min<size_t>(y.size() - done, 1 + done % 777));
            limiter.process(y.data() + done, count);
            done += static_cast<size_t>(count);
        }
        // Output samples are floats: the bound is the ceiling as a float sample value.
        float worst = 0.0f;
        for (float v : y) worst = std::max(worst, std::abs(v));
        EXPECT_LE(worst, static_cast<float>(s.ceiling)) << name << "; " << describe(s);
    }
}

TEST_P(LimiterSettingsCase, NonFiniteInputActsAsZero) {
    const LimiterSettings s = GetParam();
    const auto n = static_cast<size_t>(0.5 * s.fs);
    std::vector<float> with_bad = test::sine(150.0, s.fs, n, 2.0), with_zeros = with_bad;
    const float bad[] = {std::numeric_limits<float>::quiet_NaN(),
                         std::numeric_limits<float>::infinity(),
                         -std::numeric_limits<float>::infinity()};
    for (size_t i = 50, k = 0; i < n; i += 301, ++k) {
        with_bad[i] = bad[k % 3];
        with_zeros[i] = 0.0f;
    }
    PeakLimiter a = make(s), b = make(s);
    a.process(with_bad.data(), static_cast<int>(n));
    b.process(with_zeros.data(), static_cast<int>(n));
    for (size_t i = 0; i < n; ++i) {
        ASSERT_TRUE(std::isfinite(with_bad[i])) << "sample " << i << "; " << describe(s);
        ASSERT_EQ(with_bad[i], with_zeros[i]) << "sample " << i << "; " << describe(s);
    }
}

TEST_P(LimiterSettingsCase, ExtremeFiniteInputGivesFiniteBoundedOutput) {
    const LimiterSettings s = GetParam();
    std::vector<float> x(4096, 0.0f);
    for (size_t i = 0; i < x.size(); i += 3)
        x[i] = (i % 2 ? -1.0f : 1.0f) * std::numeric_limits<float>::max();
    PeakLimiter limiter = make(s);
    limiter.process(x.data(), static_cast<int>(x.size()));
    for (float v : x) {
        ASSERT_TRUE(std::isfinite(v)) << describe(s);
        ASSERT_LE(std::abs(v), static_cast<float>(s.ceiling)) << describe(s);
    }
}

TEST_P(LimiterSettingsCase, LatencyIsTheLookahead) {
    const LimiterSettings s = GetParam();
    PeakLimiter limiter = make(s);
    const int expected = std::max(1, static_cast<int>(std::llround(s.lookahead_ms * 1e-3 * s.fs)));
    EXPECT_EQ(limiter.latency(), expected);
}

INSTANTIATE_TEST_SUITE_P(Settings, LimiterSettingsCase,
                         ::testing::Values(LimiterSettings{48000, 1.5, 80, 0, -6, 1.0},
                                           LimiterSettings{48000, 0.1, 1, 40, -6, 1.0},
                                           LimiterSettings{44100, 20, 2000, 0, -40,
                                                           0.8912509381337456},
                                           LimiterSettings{8000, 1.5, 80, 20, 0, 0.5},
                                           LimiterSettings{192000, 5, 10, -10, -20, 0.1}));

TEST(PeakLimiter, BelowThresholdPassesUnchangedApartFromLatency) {
    for (double fs : {8000.0, 48000.0, 192000.0}) {
        PeakLimiter limiter;
        limiter.prepare({.sample_rate_hz = fs}, 1.5,
                        {.drive_db = 0,
                         .threshold_db = -6,
                         .ceiling = 1.0,
                         .release_ms = 80});  // threshold at 0.501
        const int latency = limiter.latency();
        const auto n = static_cast<size_t>(fs / 2);
        std::vector<float> x = test::sine(97.0, fs, n, 0.5);
        for (size_t i = n / 2; i < n; ++i) x[i] = static_cast<float>(0.45 * std::sin(0.01 * i));
        std::vector<float> y = x;
        limiter.process(y.data(), static_cast<int>(n));
        for (int i = 0; i < latency; ++i) ASSERT_EQ(y[i], 0.0f) << i;
        for (size_t i = static_cast<size_t>(latency); i < n; ++i)
            ASSERT_EQ(y[i], x[i - latency]) << "sample " << i << " at " << fs;
    }
}

TEST(PeakLimiter, DriveScalesATransparentSignal) {
    PeakLimiter limiter;
    limiter.prepare({.sample_rate_hz = 48000}, 2,
                    {.drive_db = -6, .threshold_db = -3, .ceiling = 1.0, .release_ms = 80});
    const double drive = db_to_gain(-6);
    std::vector<float> x = test::sine(220.0, 48000, 4800, 0.9), y = x;
    limiter.process(y.data(), static_cast<int>(y.size()));
    const int latency = limiter.latency();
    for (size_t i = static_cast<size_t>(latency); i < y.size(); ++i)
        ASSERT_EQ(y[i], static_cast<float>(static_cast<double>(x[i - latency]) * drive)) << i;
}

TEST(PeakLimiter, LimitsToTheStaticCurveAndKeepsLouderLouder) {
    const double fs = 48000;
    const double amplitudes[] = {0.7, 1.0, 2.0, 4.0, 8.0};
    double previous_peak = 0.0;
    for (double a : amplitudes) {
        PeakLimiter limiter;
        limiter.prepare({.sample_rate_hz = fs}, 1.5,
                        {.drive_db = 0, .threshold_db = -6, .ceiling = 1.0, .release_ms = 80});
        std::vector<float> x = test::sine(100.0, fs, static_cast<size_t>(fs), a);
        limiter.process(x.data(), static_cast<int>(x.size()));
        const double out_peak = test::peak(std::span<const float>(x).subspan(x.size() / 2));
        EXPECT_LE(out_peak, limiter.curve(a) + 1e-6) << "amplitude " << a;
        EXPECT_GE(out_peak, limiter.curve(a) - 0.03) << "amplitude " << a;
        EXPECT_GT(out_peak, previous_peak) << "amplitude " << a;
        previous_peak = out_peak;
    }
}

TEST(PeakLimiter, CurveIsTheDocumentedSoftKnee) {
    PeakLimiter limiter;
    limiter.prepare({.sample_rate_hz = 48000}, 1.5,
                    {.drive_db = 0, .threshold_db = -6, .ceiling = 1.0, .release_ms = 80});
    const double t = db_to_gain(-6), c = 1.0;
    for (double p : {0.0, 0.1, 0.25, t}) EXPECT_DOUBLE_EQ(limiter.curve(p), p) << p;
    for (double p : {0.6, 1.0, 2.0, 5.0})
        EXPECT_NEAR(limiter.curve(p), t + (c - t) * ((p - t) / (c - t)) / (1 + (p - t) / (c - t)),
                    1e-12);
    // Continuous with slope 1 at the knee.
    const double h = 1e-7;
    EXPECT_NEAR((limiter.curve(t + h) - limiter.curve(t)) / h, 1.0, 1e-5);
}

// The header promises the order of dynamics is kept: louder input always louder output, the
// ceiling never reached. Post-processing allows drive up to +40 dB, so full-scale input reaches
// the curve at 100.
TEST(PeakLimiter, CurveIsStrictlyIncreasingAndBelowTheCeilingUpToFullScaleAtMaxDrive) {
    for (double threshold_db : {-6.0, -20.0}) {
        PeakLimiter limiter;
        limiter.prepare(
            {.sample_rate_hz = 48000}, 1.5,
            {.drive_db = 40, .threshold_db = threshold_db, .ceiling = 1.0, .release_ms = 80});
        double previous = limiter.curve(0.0);
        int failures = 0;
        for (int i = 1; i <= 4000 && failures < 5; ++i) {
            const double p = 1e-6 * std::pow(1e8, i / 4000.0);  // 1e-6 ... 100
            const double y = limiter.curve(p);
            if (!(y > previous && y < 1.0)) {
                ADD_FAILURE() << "threshold " << threshold_db << " dB: curve(" << p << ") = " << y
                              << " (previous " << previous << ", ceiling 1)";
                ++failures;
            }
            previous = y;
        }
    }
}

TEST(PeakLimiter, ResetGivesTheSameOutputAgain) {
    PeakLimiter limiter;
    limiter.prepare({.sample_rate_hz = 48000}, 1.5,
                    {.drive_db = 10, .threshold_db = -6, .ceiling = 1.0, .release_ms = 80});
    std::vector<float> a = test::white_noise(20000, 5, 2.0), b = a;
    limiter.process(a.data(), static_cast<int>(a.size()));
    limiter.reset();
    limiter.process(b.data(), static_cast<int>(b.size()));
    EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace tactus
