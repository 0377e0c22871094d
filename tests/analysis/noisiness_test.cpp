// Noisiness (Bark-band spectral flatness) through StftFrame: seeded white noise reads > 0.8
// (mean of several frames), a sine < 0.05, silence 0, and the value stays in [0, 1].
#include "tactus/analysis/noisiness.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/signals.hpp"
#include "tactus/analysis/stft_frame.hpp"
#include "tactus/dsp/sample_history.hpp"

namespace tactus {
namespace {

// Mean noisiness over `frames` frames, one every window/2 samples.
double mean_noisiness(const std::vector<float>& x, double fs, int window, int frames) {
    StftFrame stft;
    stft.prepare(window, fs);
    Noisiness noisiness;
    noisiness.prepare(stft.bins(), stft.bin_hz());
    SampleHistory history;
    history.prepare(window);
    double sum = 0.0;
    size_t position = 0;
    history.write(x.data(), window);
    position += static_cast<size_t>(window);
    for (int f = 0; f < frames; ++f) {
        stft.analyse(history);
        const double v = noisiness.compute(stft.powers());
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
        sum += v;
        history.write(x.data() + position, window / 2);
        position += static_cast<size_t>(window / 2);
    }
    return sum / frames;
}

TEST(Noisiness, WhiteNoiseIsNoisy) {
    for (double fs : {44100.0, 48000.0}) {
        for (uint64_t seed : {1u, 2u, 3u}) {
            const auto x = test::white_noise(40000, seed, 0.5);
            const double v = mean_noisiness(x, fs, 2048, 8);
            EXPECT_GT(v, 0.8) << "seed " << seed << " at " << fs;
        }
    }
}

TEST(Noisiness, SineIsTonal) {
    for (double f : {110.0, 440.0, 1000.0, 3000.0}) {
        const auto x = test::sine(f, 48000, 40000, 0.5);
        EXPECT_LT(mean_noisiness(x, 48000, 2048, 8), 0.05) << f << " Hz";
    }
}

TEST(Noisiness, SilenceReadsZero) {
    const std::vector<float> x(40000, 0.0f);
    EXPECT_EQ(mean_noisiness(x, 48000, 2048, 4), 0.0);
}

}  // namespace
}  // namespace tactus
