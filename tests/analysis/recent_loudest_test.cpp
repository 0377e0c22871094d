// RecentLoudest: how far a band's power rose, at an onset's decision, over its loudest in the
// 50 ms before the onset (analysis/recent_loudest.hpp), on a stream of per-frame powers.
#include "tactus/analysis/recent_loudest.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tactus {
namespace {

constexpr double kRate = 16000;
constexpr int kHop = 23;    // 1.45 ms
constexpr int kWait = 200;  // the most samples an onset's start lies before its decision

// The rise read at the frame ending at `now`, of an onset that started at `start`, after
// `powers`, one a frame, the last ending at `now`.
float rise_after(const std::vector<double>& powers, int64_t now, int64_t start) {
    RecentLoudest recent;
    recent.prepare(kHop, kRate, kWait);
    for (const double p : powers) recent.push(p);
    return recent.rise(now, start);
}

// A quiet bed, then a hit 100 times its power: a rise of 2 (log10), whatever came more than 50 ms
// before; a louder burst 20-30 ms before the hit is what it must beat.
TEST(RecentLoudest, RisesOverTheLoudestOfTheLast50Ms) {
    const int frames = 200, hit = 190;  // the hit's first frame
    std::vector<double> powers(frames, 1e-4);
    for (int f = hit; f < frames; ++f) powers[f] = 1e-2;
    const int64_t now = int64_t{frames} * kHop, start = int64_t{hit} * kHop - kHop / 2;
    EXPECT_NEAR(rise_after(powers, now, start), 2.0, 1e-6);

    std::vector<double> old_burst = powers;  // 70-80 ms before: out of the span
    for (int f = hit - 55; f < hit - 48; ++f) old_burst[f] = 1.0;
    EXPECT_NEAR(rise_after(old_burst, now, start), 2.0, 1e-6);

    std::vector<double> recent_burst = powers;  // 20-30 ms before: the loudest to beat
    for (int f = hit - 20; f < hit - 14; ++f) recent_burst[f] = 1.0;
    EXPECT_NEAR(rise_after(recent_burst, now, start), -2.0, 1e-6);
}

// The hit's own frames are never its reference: a start up to a margin after a frame's end
// leaves that frame out, and the power now is over the frames since the start alone.
TEST(RecentLoudest, TheHitsOwnFramesAreNotTheBed) {
    std::vector<double> powers(100, 1e-4);
    powers[98] = powers[99] = 1e-2;
    const int64_t now = 100 * kHop, start = 98 * kHop;  // the two newest frames are the hit's
    EXPECT_NEAR(rise_after(powers, now, start), 2.0, 1e-6);
    // Decided in the hit's first frame: the power now is that frame's alone.
    powers[98] = 1e-4;
    EXPECT_NEAR(rise_after(powers, now, 99 * kHop), 2.0, 1e-6);
}

}  // namespace
}  // namespace tactus
