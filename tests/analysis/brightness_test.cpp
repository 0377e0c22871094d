// Brightness (log-frequency spectral centroid: magnitude-weighted geometric mean frequency)
// through StftFrame on a SampleHistory: a sine reads its own frequency within a few Hz at 500,
// 1000 and 3000 Hz, two sines of equal amplitude read their geometric mean, DC is excluded,
// silence reads 0, bins above max_hz do not count.
#include "tactus/analysis/brightness.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/signals.hpp"
#include "tactus/analysis/stft_frame.hpp"
#include "tactus/dsp/sample_history.hpp"

namespace tactus {
namespace {

constexpr double kWholeBand = 1e9;

double centroid_of(const std::vector<float>& x, double fs, int window, double max_hz = kWholeBand) {
    StftFrame stft;
    stft.prepare(window, fs);
    SampleHistory history;
    history.prepare(window);
    history.write(x.data(), static_cast<int>(x.size()));
    stft.analyse(history);
    Brightness brightness;
    brightness.prepare(stft.bins(), stft.bin_hz(), max_hz);
    return brightness.centroid_hz(stft.magnitudes());
}

TEST(Brightness, SineReadsItsFrequency) {
    struct Case {
        double fs;
        int window;
    };
    for (const auto [fs, window] : {Case{48000, 2048}, Case{44100, 1024}, Case{96000, 4096}}) {
        for (double f : {500.0, 1000.0, 3000.0}) {
            for (double phase : {0.0, 1.0}) {
                const auto x = test::sine(f, fs, 3 * static_cast<size_t>(window), 0.5, phase);
                EXPECT_NEAR(centroid_of(x, fs, window), f, 3.0)
                    << f << " Hz at " << fs << " Hz, window " << window;
            }
        }
    }
}

TEST(Brightness, TwoEqualSinesReadTheirGeometricMean) {
    const double fs = 48000;
    auto x = test::sine(250.0, fs, 6000, 0.3);
    const auto y = test::sine(4000.0, fs, 6000, 0.3, 0.7);
    for (size_t i = 0; i < x.size(); ++i) x[i] += y[i];
    EXPECT_NEAR(centroid_of(x, fs, 2048), 1000.0, 10.0);  // sqrt(250 * 4000)
}

TEST(Brightness, SilenceReadsZero) {
    const std::vector<float> x(4096, 0.0f);
    EXPECT_EQ(centroid_of(x, 48000, 2048), 0.0);
    const std::vector<float> spectrum(100, 0.0f);
    Brightness brightness;
    brightness.prepare(100, 10.0, kWholeBand);
    EXPECT_EQ(brightness.centroid_hz(spectrum), 0.0);
}

TEST(Brightness, DcIsExcluded) {
    std::vector<float> spectrum(64, 0.0f);
    spectrum[0] = 1000.0f;
    spectrum[10] = 1.0f;
    Brightness brightness;
    brightness.prepare(64, 20.0, kWholeBand);
    EXPECT_NEAR(brightness.centroid_hz(spectrum), 200.0, 1e-9);
}

// What lies above max_hz does not count: a 250 Hz body with a 4 kHz click reads the body alone,
// and the same again after a live change back to the whole band reads their geometric mean.
TEST(Brightness, OnlyBinsUpToMaxHzCount) {
    const double fs = 48000;
    auto x = test::sine(250.0, fs, 6000, 0.3);
    const auto y = test::sine(4000.0, fs, 6000, 0.3, 0.7);
    for (size_t i = 0; i < x.size(); ++i) x[i] += y[i];
    EXPECT_NEAR(centroid_of(x, fs, 2048, 1500.0), 250.0, 5.0);
    std::vector<float> spectrum(64, 0.0f);
    spectrum[10] = 1.0f;  // 200 Hz
    spectrum[40] = 1.0f;  // 800 Hz
    Brightness brightness;
    brightness.prepare(64, 20.0, 500.0);
    EXPECT_NEAR(brightness.centroid_hz(spectrum), 200.0, 1e-9);
    brightness.set_max_hz(kWholeBand);
    EXPECT_NEAR(brightness.centroid_hz(spectrum), 400.0, 1e-9);  // sqrt(200 * 800)
}

}  // namespace
}  // namespace tactus
