// The delay line: exact delays, every channel alike, a delay that moves at once or by a
// crossfade without a click, never beyond the ring allocated by prepare().
#include "tactus/dsp/delay_line.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {

constexpr double kRateHz = 44100;

std::vector<float> tone(size_t n) {  // a steady tone: any jump in it is a click
    std::vector<float> x(n);
    for (size_t i = 0; i < n; ++i)
        x[i] = static_cast<float>(0.5 *
                                  std::sin(2 * kPi * 220 * static_cast<double>(i) / kRateHz + 0.3));
    return x;
}

std::vector<float> ramp(size_t n) {
    std::vector<float> x(n);
    for (size_t i = 0; i < n; ++i) x[i] = static_cast<float>(i + 1);
    return x;
}

// Runs x through `delay` in place in blocks of `block`, asking for `next_delay` at sample
// `change_at`.
std::vector<float> delayed(DelayLine& delay, const std::vector<float>& x, int block,
                           size_t change_at, int next_delay) {
    std::vector<float> y = x;
    for (size_t at = 0; at < y.size(); at += static_cast<size_t>(block)) {
        if (at <= change_at && change_at < at + static_cast<size_t>(block))
            delay.set_delay_samples(next_delay);
        float* channel = y.data() + at;
        delay.process(&channel, static_cast<int>(std::min<size_t>(block, y.size() - at)));
    }
    return y;
}

TEST(DelayLine, DelaysEveryChannelExactlyWithSilenceBefore) {
    const std::vector<float> x = ramp(1000);
    for (const int d : {0, 1, 37, 300}) {
        DelayLine delay;
        delay.prepare(2, 300, d);
        std::vector<float> left(x.size()), right(x.size());
        for (size_t at = 0; at < x.size(); at += 64) {  // separate input and output buffers
            const int count = static_cast<int>(std::min<size_t>(64, x.size() - at));
            const float* in[] = {x.data() + at, x.data() + at};
            float* out[] = {left.data() + at, right.data() + at};
            delay.process(in, out, count);
        }
        for (size_t n = 0; n < x.size(); ++n)
            ASSERT_EQ(left[n], n >= static_cast<size_t>(d) ? x[n - d] : 0.0f) << d << " " << n;
        EXPECT_EQ(left, right);
    }
}

TEST(DelayLine, MovesAtOnceWithoutAFade) {
    const std::vector<float> x = ramp(3000);
    DelayLine delay;
    delay.prepare(1, 500, 100);
    const std::vector<float> y = delayed(delay, x, 64, 1000, 400);
    for (size_t n = 0; n < 960; ++n) ASSERT_EQ(y[n], n >= 100 ? x[n - 100] : 0.0f) << n;
    for (size_t n = 960; n < y.size(); ++n) ASSERT_EQ(y[n], x[n - 400]) << n;
    delay.reset();
    float silence[64] = {};
    float* channel = silence;
    delay.process(&channel, 64);
    EXPECT_EQ(*std::max_element(silence, silence + 64), 0.0f) << "reset: silent rings";
    EXPECT_EQ(delay.delay_samples(), 400) << "reset keeps the delay";
}

TEST(DelayLine, MovesToTheNewDelayByACrossfadeWithoutAClick) {
    const std::vector<float> x = tone(20000);
    constexpr int kFrom = 113, kTo = 203, kFade = 441, kBlock = 64;
    for (const auto& [from, to] : {std::pair{kFrom, kTo}, std::pair{kTo, kFrom}}) {
        DelayLine delay;
        delay.prepare(1, 1000, from, kFade);
        const std::vector<float> y = delayed(delay, x, kBlock, 5000, to);
        const auto a = [&](size_t n) {
            return n >= static_cast<size_t>(from) ? x[n - from] : 0.0f;
        };
        const auto b = [&](size_t n) { return n >= static_cast<size_t>(to) ? x[n - to] : 0.0f; };
        size_t first_b = y.size(), last_a = 0;  // the crossfade lies between
        for (size_t n = 0; n < y.size(); ++n) {
            if (y[n] == a(n)) last_a = n;
            if (y[n] != b(n)) first_b = n + 1;
        }
        EXPECT_EQ(last_a + 1, 4992u) << "the old delay up to the block of the change";
        EXPECT_EQ(first_b, 4992u + kFade - 1) << "the new delay after one crossfade";
        EXPECT_EQ(delay.delay_samples(), to);
        float largest_step = 0, allowed = 0;
        for (size_t n = kTo + 1; n < y.size(); ++n) {  // both positions in the tone
            largest_step = std::max(largest_step, std::abs(y[n] - y[n - 1]));
            allowed = std::max({allowed, std::abs(a(n) - a(n - 1)), std::abs(b(n) - b(n - 1))});
        }
        // The tone's own largest step, plus the crossfade's share of the two positions' gap.
        EXPECT_LE(largest_step, allowed + 1.0f / kFade + 1e-6f) << from << " -> " << to;
        // An immediate move would step by the gap between the two positions.
        EXPECT_GT(std::abs(a(4992) - b(4992)), 20 * (allowed + 1.0f / kFade));
    }
}

TEST(DelayLine, ClampsToItsRingAndFinishesOneMoveBeforeTheNext) {
    DelayLine delay;
    delay.prepare(2, 300, 5000, 100);
    EXPECT_EQ(delay.delay_samples(), 300) << "the ring holds 300 at most";
    EXPECT_EQ(delay.max_delay_samples(), 300);
    delay.set_delay_samples(-4);
    EXPECT_EQ(delay.delay_samples(), 0);
    std::vector<float> left = ramp(1000), right = ramp(1000);
    float* channels[] = {left.data(), right.data()};
    delay.set_delay_samples(10);
    delay.process(channels, 50);  // a move from 300 to 10 begins...
    delay.set_delay_samples(20);  // ...and this one waits for it
    float* next[] = {left.data() + 50, right.data() + 50};
    delay.process(next, 450);  // the first move ends; the second one begins in the next call
    float* last[] = {left.data() + 500, right.data() + 500};
    delay.process(last, 500);
    EXPECT_EQ(left, right) << "every channel delayed alike";
    EXPECT_FLOAT_EQ(left[999], 1000 - 20);
}

}  // namespace
}  // namespace tactus
