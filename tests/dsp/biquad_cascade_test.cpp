// cascade_each (the wavefront on SSE2) against the sections applied one after the other with
// Biquad::process: the same doubles bit for bit, in order, and the same states after, for any
// block split and any number of sections. cascades_each, chains side by side, against each
// chain's own cascade_each, each on its own input.
#include "tactus/dsp/biquad_cascade.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace tactus {
namespace {

constexpr double kRateHz = 48000;

template <int N>
std::array<Biquad, N> sections() {
    std::array<Biquad, N> made;
    for (int s = 0; s < N; ++s)
        made[s].set(
            s % 2 == 0
                ? BiquadCoefficients::lowpass(150.0 * (s + 1), butterworth_q(4, s % 2), kRateHz)
                : BiquadCoefficients::highpass(40.0 * s, butterworth_q(4, s % 2), kRateHz));
    return made;
}

std::vector<float> signal(int count) {
    std::vector<float> x(static_cast<size_t>(count));
    uint32_t noise = 1;
    for (int i = 0; i < count; ++i) {
        noise = noise * 1664525u + 1013904223u;
        x[i] = static_cast<float>(0.5 * std::sin(0.01 * i) + (noise >> 8) * 0x1p-25 - 0.25);
    }
    return x;
}

template <int N>
void expect_serial(int block) {
    const std::vector<float> x = signal(1000);
    std::array<Biquad, N> serial = sections<N>(), fast = sections<N>();
    std::vector<double> want, got;
    for (float v : x) {
        double y = v;
        for (auto& s : serial) y = s.process(y);
        want.push_back(y);
    }
    for (int at = 0; at < static_cast<int>(x.size()); at += block) {
        const int count = std::min(block, static_cast<int>(x.size()) - at);
        cascade_each<N>(
            fast.data(), count, [&](int i) { return static_cast<double>(x[at + i]); },
            [&](int i, double y) {
                EXPECT_EQ(static_cast<int>(got.size()), at + i);  // in order, each once
                got.push_back(y);
            });
    }
    ASSERT_EQ(got.size(), want.size());
    EXPECT_EQ(std::memcmp(got.data(), want.data(), want.size() * sizeof(double)), 0)
        << N << " sections, blocks of " << block;
    for (int s = 0; s < N; ++s) EXPECT_EQ(fast[s].state(), serial[s].state()) << "section " << s;
}

TEST(BiquadCascade, EachIsTheSectionsInTurnBitForBit) {
    for (int block : {1, 2, 3, 7, 64, 333, 1000}) {
        expect_serial<1>(block);
        expect_serial<2>(block);
        expect_serial<3>(block);
        expect_serial<4>(block);
        expect_serial<11>(block);
    }
}

// Chains of A and B sections side by side, each on its own input (the second's reversed).
template <int A, int B>
void expect_side_by_side(int block) {
    const std::vector<float> x = signal(1000);
    std::vector<float> reversed(x.rbegin(), x.rend());
    const std::array<const std::vector<float>*, 2> inputs{&x, &reversed};
    std::array<Biquad, A> a = sections<A>(), a_alone = sections<A>();
    std::array<Biquad, B> b = sections<B>(), b_alone = sections<B>();
    std::array<std::vector<double>, 2> want, got;
    for (int at = 0; at < static_cast<int>(x.size()); at += block) {
        const int count = std::min(block, static_cast<int>(x.size()) - at);
        cascade_each<A>(
            a_alone.data(), count, [&](int i) { return static_cast<double>(x[at + i]); },
            [&](int, double y) { want[0].push_back(y); });
        cascade_each<B>(
            b_alone.data(), count, [&](int i) { return static_cast<double>(reversed[at + i]); },
            [&](int, double y) { want[1].push_back(y); });
        int last_chain = 1, last_i = -1;
        cascades_each<A, B>(
            {a.data(), b.data()}, count,
            [&](int c, int i) { return static_cast<double>((*inputs[c])[at + i]); },
            [&](int c, int i, double y) {
                EXPECT_EQ(static_cast<int>(got[c].size()), at + i);  // in order, each once
                if (A == B) {  // at each i the chains in order
                    EXPECT_TRUE(i > last_i || (i == last_i && c > last_chain));
                }
                last_chain = c, last_i = i;
                got[c].push_back(y);
            });
    }
    for (int c = 0; c < 2; ++c) {
        ASSERT_EQ(got[c].size(), x.size());
        EXPECT_EQ(std::memcmp(got[c].data(), want[c].data(), x.size() * sizeof(double)), 0)
            << A << " and " << B << " sections, chain " << c << ", blocks of " << block;
    }
    for (int s = 0; s < A; ++s) EXPECT_EQ(a[s].state(), a_alone[s].state()) << "a " << s;
    for (int s = 0; s < B; ++s) EXPECT_EQ(b[s].state(), b_alone[s].state()) << "b " << s;
}

TEST(BiquadCascade, ChainsSideBySideAreEachChainBitForBit) {
    for (int block : {1, 2, 3, 7, 64, 333, 1000}) {
        expect_side_by_side<2, 2>(block);  // K-weighting, two channels
        expect_side_by_side<2, 4>(block);  // the low and the high band
        expect_side_by_side<1, 5>(block);
        expect_side_by_side<4, 3>(block);
    }
}

}  // namespace
}  // namespace tactus
