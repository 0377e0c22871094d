// StftFrame: a full-scale sine centred on a bin reads magnitude 1 there (Hann, periodic,
// scaled), powers are squared magnitudes, bin_hz = fs / N, and the frame covers the newest
// window_samples() of the history.
#include "tactus/analysis/stft_frame.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/signals.hpp"

namespace tactus {
namespace {

TEST(StftFrame, FullScaleSineOnABinReadsOne) {
    for (double fs : {8000.0, 48000.0, 192000.0}) {
        const int n = 1024;
        StftFrame stft;
        stft.prepare(n, fs);
        EXPECT_EQ(stft.window_samples(), n);
        EXPECT_EQ(stft.bins(), n / 2 + 1);
        EXPECT_DOUBLE_EQ(stft.bin_hz(), fs / n);
        SampleHistory history;
        history.prepare(2 * n);
        const int k0 = 37;
        const auto x = test::sine(k0 * stft.bin_hz(), fs, 3 * n, 1.0, 0.3);
        history.write(x.data(), static_cast<int>(x.size()));
        stft.analyse(history);
        EXPECT_NEAR(stft.magnitudes()[k0], 1.0, 1e-4);
        EXPECT_NEAR(stft.magnitudes()[k0 - 1], 0.5, 1e-4);  // Hann: neighbours at -6 dB
        EXPECT_NEAR(stft.magnitudes()[k0 + 2], 0.0, 1e-4);
        for (int k = 0; k < stft.bins(); ++k)
            ASSERT_NEAR(stft.powers()[k], stft.magnitudes()[k] * stft.magnitudes()[k], 1e-6);
    }
}

TEST(StftFrame, AnalysesOnlyTheNewestWindow) {
    StftFrame stft;
    stft.prepare(256, 48000);
    SampleHistory history;
    history.prepare(1024);
    std::vector<float> loud = test::white_noise(512, 1), silence(256, 0.0f);
    history.write(loud.data(), 512);
    history.write(silence.data(), 256);
    stft.analyse(history);
    for (float m : stft.magnitudes()) EXPECT_EQ(m, 0.0f);
}

}  // namespace
}  // namespace tactus
