// Envelope: sample n after a trigger is the continuous envelope at time n / rate (a linear rise
// to 1 in attack_ms, then a decay of 60 dB in decay_ms, the peak between samples if it falls
// there); the decay snaps to exact 0; a retrigger during the decay (or attack) rises from the
// current level without a jump; a sustain level is approached and held.
#include "tactus/synthesis/envelope.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tactus {
namespace {

// Runs the envelope until the first sample past its peak.
void run_past_peak(Envelope& env) {
    double previous = env.level();
    while (true) {
        env.next();
        if (env.level() <= previous) return;
        previous = env.level();
    }
}

struct EnvelopeSetting {
    double fs, attack_ms, decay_ms;
};

class EnvelopeCase : public ::testing::TestWithParam<EnvelopeSetting> {};

TEST_P(EnvelopeCase, SamplesTheContinuousAttackAndDecay) {
    const auto [fs, attack_ms, decay_ms] = GetParam();
    Envelope env;
    env.prepare({.sample_rate_hz = fs});
    env.set_shape(attack_ms, decay_ms, 0.0);
    env.trigger();
    const double peak_samples = std::max(1.0, attack_ms * 1e-3 * fs);
    const double decay_per_sample = std::pow(10.0, -3.0 / std::max(1.0, decay_ms * 1e-3 * fs));
    for (int n = 0; n < 3 * peak_samples + 10; ++n) {
        const double level =
            n <= peak_samples ? n / peak_samples : std::pow(decay_per_sample, n - peak_samples);
        if (n > peak_samples && level < 1e-6) break;  // near the -140 dB snap to 0
        ASSERT_NEAR(env.next(), level, 1e-9) << "sample " << n;
    }
}

TEST_P(EnvelopeCase, DecayFallsSixtyDbInDecayMs) {
    const auto [fs, attack_ms, decay_ms] = GetParam();
    Envelope env;
    env.prepare({.sample_rate_hz = fs});
    env.set_shape(attack_ms, decay_ms, 0.0);
    env.trigger();
    run_past_peak(env);
    int samples = 0;
    double previous = 1.0;
    while (env.level() > 1e-3) {
        const double level = env.next();
        ASSERT_LT(level, previous);
        previous = level;
        ++samples;
    }
    const double expected = decay_ms * 1e-3 * fs;
    EXPECT_NEAR(samples, expected, 0.02 * expected + 1);
    // Then it reaches exact zero (levels below -140 dB snap to 0) and stays there.
    for (int i = 0; i < 10 * expected && env.level() > 0.0; ++i) env.next();
    EXPECT_EQ(env.level(), 0.0);
    EXPECT_EQ(env.next(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, EnvelopeCase,
    ::testing::Values(EnvelopeSetting{48000, 1, 150}, EnvelopeSetting{48000, 10, 5},
                      EnvelopeSetting{44100, 0.5, 1000}, EnvelopeSetting{8000, 100, 5000},
                      EnvelopeSetting{192000, 3, 60}, EnvelopeSetting{8000, 0.1, 5}));

TEST(Envelope, RetriggerDuringDecayRisesFromTheCurrentLevel) {
    const double fs = 48000;
    Envelope env;
    env.prepare({.sample_rate_hz = fs});
    env.set_shape(2.0, 100.0, 0.0);
    env.trigger();
    run_past_peak(env);
    while (env.level() > 0.3) env.next();
    const double before = env.level(), step = 1.0 / (2e-3 * fs);
    env.trigger();
    std::vector<double> rise{env.next()};
    for (double level = env.next(); level > rise.back(); level = env.next()) rise.push_back(level);
    EXPECT_EQ(rise.front(), before);  // no jump: the rise starts from the current level
    // Attack steps up to the peak; the sample just past it has decayed for part of its step.
    for (size_t i = 1; i + 1 < rise.size(); ++i)
        ASSERT_NEAR(rise[i] - rise[i - 1], step, 1e-12) << "sample " << i;
    EXPECT_LE(rise.back() - rise[rise.size() - 2], step + 1e-12);
    EXPECT_GT(rise.back(), 1.0 - step);
    EXPECT_LE(rise.back(), 1.0);
}

TEST(Envelope, RetriggerDuringAttackContinuesTheRise) {
    Envelope env;
    env.prepare({.sample_rate_hz = 48000});
    env.set_shape(5.0, 100.0, 0.0);
    env.trigger();
    for (int i = 0; i < 100; ++i) env.next();
    const double before = env.level();
    env.trigger();
    EXPECT_EQ(env.next(), before);
    EXPECT_NEAR(env.level() - before, 1.0 / 240.0, 1e-12);
}

TEST(Envelope, SustainLevelIsApproachedAndHeld) {
    const double fs = 48000;
    for (double sustain : {0.1, 0.5, 0.9}) {
        Envelope env;
        env.prepare({.sample_rate_hz = fs});
        env.set_shape(1.0, 50.0, sustain);
        env.trigger();
        run_past_peak(env);
        // The distance to the sustain level falls 60 dB in decay_ms.
        for (int i = 0; i < 2400; ++i) env.next();
        EXPECT_NEAR((env.level() - sustain) / (1.0 - sustain), 1e-3, 1e-4) << sustain;
        for (int i = 0; i < 48000; ++i) env.next();
        for (int i = 0; i < 48000; ++i) ASSERT_NEAR(env.next(), sustain, 1e-9) << sustain;
    }
}

TEST(Envelope, SilentUntilTriggeredAndAfterReset) {
    Envelope env;
    env.prepare({.sample_rate_hz = 48000});
    env.set_shape(1.0, 150.0, 0.0);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(env.next(), 0.0);
    env.trigger();
    env.next();
    EXPECT_GT(env.level(), 0.0);
    env.reset();
    EXPECT_EQ(env.level(), 0.0);
    EXPECT_EQ(env.next(), 0.0);
}

}  // namespace
}  // namespace tactus
