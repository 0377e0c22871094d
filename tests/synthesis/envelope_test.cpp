// Envelope: the attack rises linearly to exactly 1 in attack_ms; the decay falls 60 dB in
// decay_ms (+-2 %) and snaps to exact 0; a retrigger during the decay (or attack) rises from
// the current level without a jump; a sustain level is approached and held.
#include "tactus/synthesis/envelope.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tactus {
namespace {

struct Case {
    double fs, attack_ms, decay_ms;
};

class EnvelopeCase : public ::testing::TestWithParam<Case> {};

TEST_P(EnvelopeCase, AttackReachesOneInAttackMs) {
    const auto [fs, attack_ms, decay_ms] = GetParam();
    Envelope env;
    env.prepare(fs);
    env.set_shape(attack_ms, decay_ms, 0.0);
    env.trigger();
    const double expected = std::max(1.0, attack_ms * 1e-3 * fs);
    int samples = 0;
    double previous = 0.0;
    while (env.level() < 1.0 && samples < 10 * expected + 10) {
        const double level = env.next();
        ++samples;
        ASSERT_GT(level, previous) << "attack must rise, sample " << samples;
        // Linear steps; the last one only closes the gap to exactly 1.
        ASSERT_NEAR(level - previous, std::min(1.0 / expected, 1.0 - previous), 1e-9)
            << "linear, sample " << samples;
        previous = level;
    }
    EXPECT_EQ(env.level(), 1.0);
    EXPECT_NEAR(samples, expected, std::max(1.0, 0.02 * expected));
}

TEST_P(EnvelopeCase, DecayFallsSixtyDbInDecayMs) {
    const auto [fs, attack_ms, decay_ms] = GetParam();
    Envelope env;
    env.prepare(fs);
    env.set_shape(attack_ms, decay_ms, 0.0);
    env.trigger();
    while (env.level() < 1.0) env.next();
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

INSTANTIATE_TEST_SUITE_P(Shapes, EnvelopeCase,
                         ::testing::Values(Case{48000, 1, 150}, Case{48000, 10, 5},
                                           Case{44100, 0.5, 1000}, Case{8000, 100, 5000},
                                           Case{192000, 3, 60}, Case{8000, 0.1, 5}));

TEST(Envelope, RetriggerDuringDecayRisesFromTheCurrentLevel) {
    const double fs = 48000;
    Envelope env;
    env.prepare(fs);
    env.set_shape(2.0, 100.0, 0.0);
    env.trigger();
    while (env.level() < 1.0) env.next();
    while (env.level() > 0.3) env.next();
    const double before = env.level(), step = 1.0 / (2e-3 * fs);
    env.trigger();
    const double first = env.next();
    EXPECT_GT(first, before);
    EXPECT_NEAR(first - before, step, 1e-12);  // no jump: one attack step up
    double previous = first;
    while (env.level() < 1.0) {
        const double level = env.next();
        ASSERT_NEAR(level - previous, std::min(step, 1.0 - previous), 1e-12);
        previous = level;
    }
    EXPECT_EQ(env.level(), 1.0);
    EXPECT_LT(env.next(), 1.0);  // and decays again
}

TEST(Envelope, RetriggerDuringAttackContinuesTheRise) {
    Envelope env;
    env.prepare(48000);
    env.set_shape(5.0, 100.0, 0.0);
    env.trigger();
    for (int i = 0; i < 100; ++i) env.next();
    const double before = env.level();
    env.trigger();
    EXPECT_NEAR(env.next() - before, 1.0 / 240.0, 1e-12);
}

TEST(Envelope, SustainLevelIsApproachedAndHeld) {
    const double fs = 48000;
    for (double sustain : {0.1, 0.5, 0.9}) {
        Envelope env;
        env.prepare(fs);
        env.set_shape(1.0, 50.0, sustain);
        env.trigger();
        while (env.level() < 1.0) env.next();
        // The distance to the sustain level falls 60 dB in decay_ms.
        for (int i = 0; i < 2400; ++i) env.next();
        EXPECT_NEAR((env.level() - sustain) / (1.0 - sustain), 1e-3, 1e-4) << sustain;
        for (int i = 0; i < 48000; ++i) env.next();
        for (int i = 0; i < 48000; ++i) ASSERT_NEAR(env.next(), sustain, 1e-9) << sustain;
    }
}

TEST(Envelope, SilentUntilTriggeredAndAfterReset) {
    Envelope env;
    env.prepare(48000);
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
