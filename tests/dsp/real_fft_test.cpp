// RealFft: a cosine on bin k reads N/2 there and ~0 elsewhere; inverse(forward(x)) = N x; sizes.
#include "tactus/dsp/real_fft.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "support/signals.hpp"

namespace tactus {
namespace {

TEST(RealFft, CosineOnABinAndRoundTrip) {
    for (int n : {64, 512, 4096}) {
        RealFft fft;
        fft.prepare(n);
        ASSERT_EQ(fft.size(), n);
        ASSERT_EQ(fft.bins(), n / 2 + 1);
        const int k0 = n / 8 + 3;
        for (int i = 0; i < n; ++i)
            fft.time()[i] = static_cast<float>(std::cos(2 * test::kTestPi * k0 * i / n));
        fft.forward();
        for (int k = 0; k < fft.bins(); ++k) {
            const double expected = k == k0 ? n / 2.0 : 0.0;
            ASSERT_NEAR(std::abs(fft.spectrum()[k]), expected, 1e-3 * n) << "n " << n << " k " << k;
        }
        const std::vector<float> x = test::white_noise(static_cast<size_t>(n), 9);
        std::copy(x.begin(), x.end(), fft.time());
        fft.forward();
        fft.inverse();
        for (int i = 0; i < n; ++i) ASSERT_NEAR(fft.time()[i] / n, x[i], 1e-5) << i;
    }
}

TEST(RealFft, PrepareAgainChangesSize) {
    RealFft fft;
    fft.prepare(256);
    fft.prepare(256);
    fft.prepare(1024);
    EXPECT_EQ(fft.size(), 1024);
    EXPECT_EQ(fft.bins(), 513);
}

}  // namespace
}  // namespace tactus
