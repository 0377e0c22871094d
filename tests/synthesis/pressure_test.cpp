// Pressure (NPIII component): a level 0 gives exact zeros; a step glides with a one-pole of time
// constant 1 / (2 pi 3 Hz) (NPIII's upper edge), never overshoots and is never negative; back
// to 0 it ends in exact zeros; the same at 4 kHz and 48 kHz.
#include "tactus/synthesis/pressure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tactus/core/units.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {

constexpr double kNpiiiHighHz = perception::info(perception::Channel::NPIII).range_high_hz;

ControlFrame pressure_frame(double level) {
    ControlFrame f;
    f.pressure = level;
    return f;
}

std::vector<float> render(Pressure& p, size_t count) {
    std::vector<float> out(count, 1.0f);
    p.process(out.data(), static_cast<int>(out.size()));
    return out;
}

TEST(Pressure, ZeroLevelIsExactZeros) {
    Pressure p;
    p.prepare({.sample_rate_hz = 48000});
    p.apply(pressure_frame(0.0));
    for (float v : render(p, 48000)) ASSERT_EQ(v, 0.0f);
}

TEST(Pressure, StepGlidesWithNpiiiTimeConstant) {
    for (double fs : {4000.0, 48000.0}) {
        Pressure p;
        p.prepare({.sample_rate_hz = fs});
        p.apply(pressure_frame(0.25));
        const std::vector<float> up = render(p, static_cast<size_t>(2 * fs));
        const double tau_s = 1.0 / (2 * kPi * kNpiiiHighHz);
        const auto at_tau = static_cast<size_t>(std::llround(tau_s * fs));
        EXPECT_NEAR(up[at_tau - 1], 0.25 * (1 - std::exp(-1.0)), 0.002) << fs;
        for (size_t i = 1; i < up.size(); ++i) {
            ASSERT_GE(up[i], up[i - 1]) << i;
            ASSERT_LE(up[i], 0.25f) << i;
        }
        EXPECT_NEAR(up.back(), 0.25, 1e-6);
        p.apply(pressure_frame(0.0));
        const std::vector<float> down = render(p, static_cast<size_t>(4 * fs));
        for (float v : down) ASSERT_GE(v, 0.0f);
        EXPECT_EQ(down.back(), 0.0f) << "back to exact zero at " << fs;
    }
}

}  // namespace
}  // namespace tactus
