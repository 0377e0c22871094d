// PitchYin: sines and band-limited sawtooths at 110, 220 and 440 Hz read within 1 % with
// confidence > 0.9 at 44.1 and 48 kHz; white noise is unvoiced (f0 0) or low-confidence;
// silence reads f0 0 with confidence 0.
#include "tactus/analysis/pitch_yin.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/signals.hpp"

namespace tactus {
namespace {

Pitch pitch_of(const std::vector<float>& x, double fs) {
    PitchYin yin;
    yin.prepare({.sample_rate_hz = fs}, {.min_hz = 50.0, .max_hz = 1500.0, .threshold = 0.15});
    SampleHistory history;
    history.prepare(yin.span_samples());
    history.write(x.data(), static_cast<int>(x.size()));
    return yin.analyse(history);
}

TEST(PitchYin, SinesAndSawtoothsWithinOnePercent) {
    for (double fs : {44100.0, 48000.0}) {
        for (double f : {110.0, 220.0, 440.0}) {
            const auto n = static_cast<size_t>(0.1 * fs);
            const Pitch s = pitch_of(test::sine(f, fs, n, 0.5), fs);
            EXPECT_NEAR(s.f0_hz, f, 0.01 * f) << "sine " << f << " at " << fs;
            EXPECT_GT(s.confidence, 0.9) << "sine " << f << " at " << fs;
            const Pitch w = pitch_of(test::sawtooth(f, fs, n, 0.5), fs);
            EXPECT_NEAR(w.f0_hz, f, 0.01 * f) << "sawtooth " << f << " at " << fs;
            EXPECT_GT(w.confidence, 0.9) << "sawtooth " << f << " at " << fs;
        }
    }
}

TEST(PitchYin, WhiteNoiseIsUnvoiced) {
    for (uint64_t seed = 1; seed <= 5; ++seed) {
        const Pitch p = pitch_of(test::white_noise(8000, seed, 0.5), 48000);
        EXPECT_TRUE(p.f0_hz == 0.0 || p.confidence < 0.5)
            << "seed " << seed << ": f0 " << p.f0_hz << ", confidence " << p.confidence;
        EXPECT_LT(p.confidence, 0.85) << "seed " << seed;
    }
}

TEST(PitchYin, SilenceReadsZero) {
    const Pitch p = pitch_of(std::vector<float>(8000, 0.0f), 48000);
    EXPECT_EQ(p.f0_hz, 0.0);
    EXPECT_EQ(p.confidence, 0.0);
}

}  // namespace
}  // namespace tactus
