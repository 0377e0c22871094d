// DcBlocker: a step (DC switched on) decays away with the corner's time constant, a tone above
// the corner passes unchanged, silence stays exact silence.
#include "tactus/dsp/dc_blocker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/signals.hpp"

namespace tactus {
namespace {

TEST(DcBlocker, RemovesAnOffset) {
    constexpr double kRate = 44100;
    DcBlocker blocker;
    blocker.prepare({.sample_rate_hz = kRate});
    std::vector<float> x(static_cast<size_t>(kRate), 0.5f);
    blocker.process(x.data(), static_cast<int>(x.size()));
    EXPECT_NEAR(x[0], 0.5f, 1e-6);  // the step passes, then decays: tau = 1 / (2 pi 10 Hz)
    const auto tau_samples =
        static_cast<size_t>(kRate / (2 * test::kTestPi * DcBlocker::kCornerHz));
    EXPECT_NEAR(x[tau_samples], 0.5 * std::exp(-1.0), 0.01);
    EXPECT_LT(std::abs(x.back()), 1e-5);
}

TEST(DcBlocker, PassesTheFeatureBand) {
    for (const double rate : {8000.0, 44100.0, 192000.0}) {
        DcBlocker blocker;
        blocker.prepare({.sample_rate_hz = rate});
        auto x = test::sine(100, rate, static_cast<size_t>(rate), 0.5);
        const auto y_reference = x;
        blocker.process(x.data(), static_cast<int>(x.size()));
        const size_t settled = static_cast<size_t>(rate / 2);
        const double ratio = test::rms(std::span(x).subspan(settled)) /
                             test::rms(std::span(y_reference).subspan(settled));
        EXPECT_NEAR(20 * std::log10(ratio), 0.0, 0.05) << rate;  // 100 Hz: -0.04 dB
    }
}

TEST(DcBlocker, SilenceStaysExactAndResetForgets) {
    DcBlocker blocker;
    blocker.prepare({.sample_rate_hz = 48000});
    std::vector<float> x(1000, 1.0f);
    blocker.process(x.data(), 1000);
    blocker.reset();
    std::vector<float> silence(1000, 0.0f);
    blocker.process(silence.data(), 1000);
    for (const float v : silence) ASSERT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace tactus
