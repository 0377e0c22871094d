// Upsampler (internal rate -> output rate): factor 1 is the identity; a constant passes at
// unity; a sine well inside the internal band keeps its level within 0.05 dB, and its images
// around the internal rate are at least 60 dB down; the output does not depend on how the
// stream is split into blocks; each factor's output is exactly its taps' sum.
#include "tactus/dsp/upsampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "support/signals.hpp"
#include "tactus/dsp/upsampler_taps.hpp"

namespace tactus {
namespace {

// Upsamples x in blocks of `block` internal samples (the output blocks matching them).
std::vector<float> upsample(const std::vector<float>& x, int factor, int block) {
    Upsampler up;
    up.prepare({.max_block = block * factor}, factor);
    std::vector<float> y(x.size() * factor);
    for (size_t done = 0; done < x.size(); done += block) {
        const int n = static_cast<int>(std::min<size_t>(block, x.size() - done));
        up.process(x.data() + done, n, y.data() + done * factor, n * factor);
    }
    return y;
}

// Amplitude of the component at frequency_hz (Hann-windowed single-bin DFT).
double amplitude_at(const std::vector<float>& y, size_t start, double frequency_hz, double fs) {
    std::complex<double> sum = 0.0;
    double window_sum = 0.0;
    const size_t n = y.size() - start;
    for (size_t i = 0; i < n; ++i) {
        const double w = 0.5 - 0.5 * std::cos(2.0 * test::kTestPi * i / n);
        sum += w * y[start + i] * std::polar(1.0, -2.0 * test::kTestPi * frequency_hz * i / fs);
        window_sum += w;
    }
    return 2.0 * std::abs(sum) / window_sum;
}

TEST(Upsampler, FactorOneIsTheIdentity) {
    const std::vector<float> x = test::white_noise(1000, 3, 0.5);
    EXPECT_EQ(upsample(x, 1, 64), x);
}

// Each factor's output is exactly its taps' sum, taken in order in float: output q F + r is
// sum_i x[q - i] taps[i][r] (the code for each factor, chosen at compile time, is that sum).
TEST(Upsampler, EveryFactorIsExactlyItsTapsSum) {
    const std::vector<float> x = test::white_noise(300, 7, 0.5);
    for (int factor = 2; factor <= Upsampler::kMaxFactor; ++factor) {
        const auto& taps = upsampler_taps_table(factor).taps;
        const std::vector<float> y = upsample(x, factor, 37);
        for (size_t q = 0; q < x.size(); ++q) {
            for (int r = 0; r < factor; ++r) {
                float expected = 0.0f;
                for (size_t i = 0; i < taps.size(); ++i)
                    expected += (q >= i ? x[q - i] : 0.0f) * taps[i][static_cast<size_t>(r)];
                ASSERT_EQ(y[q * static_cast<size_t>(factor) + static_cast<size_t>(r)], expected)
                    << "factor " << factor << ", output " << q << " * F + " << r;
            }
        }
    }
}

TEST(Upsampler, ConstantPassesAtUnity) {
    for (int factor : {2, 4, 9, 16}) {
        const std::vector<float> y = upsample(std::vector<float>(200, 0.5f), factor, 50);
        for (size_t i = 20 * factor; i < y.size(); ++i) ASSERT_NEAR(y[i], 0.5f, 1e-5) << factor;
    }
}

TEST(Upsampler, PassesTheBandAndRemovesImages) {
    const double internal_hz = 48000;
    const double tone_hz = 1000;  // the vibrotactile band's upper edge; internal rate >= 44.1 kHz
    for (int factor : {2, 4}) {
        const std::vector<float> x = test::sine(tone_hz, internal_hz, 48000, 0.5);
        const std::vector<float> y = upsample(x, factor, 480);
        const double fs = internal_hz * factor;
        const size_t settle = 1000 * factor;
        EXPECT_NEAR(20 * std::log10(amplitude_at(y, settle, tone_hz, fs) / 0.5), 0.0, 0.05)
            << factor;
        for (double image_hz : {internal_hz - tone_hz, internal_hz + tone_hz})
            EXPECT_LT(20 * std::log10(amplitude_at(y, settle, image_hz, fs) / 0.5), -60.0)
                << factor << " at " << image_hz << " Hz";
    }
}

TEST(Upsampler, OutputDoesNotDependOnTheSplit) {
    const std::vector<float> x = test::white_noise(4000, 5, 0.5);
    Upsampler up;
    up.prepare({.max_block = 4000 * 4}, 4);
    std::vector<float> whole(x.size() * 4), split(x.size() * 4);
    up.process(x.data(), static_cast<int>(x.size()), whole.data(), static_cast<int>(whole.size()));
    // Output blocks that end between internal samples: 3 outputs need 1 internal sample, etc.
    up.reset();
    const int counts[] = {3, 1, 5, 4, 13, 2};
    size_t in = 0, out = 0;
    for (int c = 0; out < split.size(); ++c) {
        const size_t count = std::min<size_t>(counts[c % 6], split.size() - out);
        const size_t needed = (out + count + 3) / 4;  // internal samples up to the last output
        up.process(x.data() + in, static_cast<int>(needed - in), split.data() + out,
                   static_cast<int>(count));
        in = needed;
        out += count;
    }
    EXPECT_EQ(split, whole);
}

}  // namespace
}  // namespace tactus
