// A cascade of biquads run over a block, its output given sample by sample to a sink (a band's
// energy, a K-weighted square) or written back (process_cascade). The sections are copied into
// locals of a size fixed at compile time, so the compiler unrolls the section loop and keeps the
// states in registers. Two or more sections also run in a wavefront (where the compiler does not
// fuse multiply-adds), two per vector: at step t, section k filters sample t - k, so all sections
// advance at once instead of one after the other. Each section does exactly Biquad::process's
// arithmetic on every sample, in the same order: the output is bit-identical to applying the
// sections in turn, for any block split.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "tactus/dsp/biquad.hpp"

namespace tactus {

namespace detail {
// cascade_each, one section after the other: the sections are copied into locals (unrolled,
// states in registers) and written back after.
template <int N, typename Input, typename Sink>
void serial_each(Biquad* sections, int count, Input input, Sink sink) noexcept {
    std::array<Biquad, N> local;
    for (int s = 0; s < N; ++s) local[s] = sections[s];
    for (int i = 0; i < count; ++i) {
        double x = input(i);
        for (int s = 0; s < N; ++s) x = local[s].process(x);
        sink(i, x);
    }
    for (int s = 0; s < N; ++s) sections[s] = local[s];
}

// cascade_each in a wavefront, two sections per vector (the compiler's generic vectors: SSE2
// on x86-64, pairs of scalars where the target has no double vectors).
template <int N, typename Input, typename Sink>
void wavefront_each(Biquad* sections, int count, Input input, Sink sink) noexcept {
    using Pair = double __attribute__((vector_size(2 * sizeof(double))));
    constexpr int V = (N + 1) / 2;  // vectors of two sections; a spare lane is a pass-through
    Pair b0[V], b1[V], b2[V], a1[V], a2[V], s1[V], s2[V], y[V];
    for (std::ptrdiff_t v = 0; v < V; ++v) {
        const BiquadCoefficients pass{};
        const BiquadCoefficients& c0 = sections[2 * v].coefficients();
        const BiquadCoefficients& c1 = 2 * v + 1 < N ? sections[2 * v + 1].coefficients() : pass;
        b0[v] = Pair{c0.b0, c1.b0};
        b1[v] = Pair{c0.b1, c1.b1};
        b2[v] = Pair{c0.b2, c1.b2};
        a1[v] = Pair{c0.a1, c1.a1};
        a2[v] = Pair{c0.a2, c1.a2};
        const auto state0 = sections[2 * v].state();
        const auto state1 = 2 * v + 1 < N ? sections[2 * v + 1].state() : std::pair{0.0, 0.0};
        s1[v] = Pair{state0.first, state1.first};
        s2[v] = Pair{state0.second, state1.second};
        y[v] = Pair{0.0, 0.0};
    }
    // One step: every lane takes its left neighbour's last output (lane 0 the new sample).
    // Lanes outside 0 <= t - k < count keep their state (`masked`).
    auto step = [&](double input, bool masked, int t) {
        Pair x[V];
        x[0] = Pair{input, y[0][0]};
        for (int v = 1; v < V; ++v) x[v] = Pair{y[v - 1][1], y[v][0]};
        for (int v = 0; v < V; ++v) {
            const Pair out = b0[v] * x[v] + s1[v];
            const Pair n1 = (b1[v] * x[v] - a1[v] * out) + s2[v];
            const Pair n2 = b2[v] * x[v] - a2[v] * out;
            if (masked) {
                for (int lane = 0; lane < 2; ++lane) {
                    const int k = 2 * v + lane;
                    if (t - k >= 0 && t - k < count) s1[v][lane] = n1[lane], s2[v][lane] = n2[lane];
                }
            } else {
                s1[v] = n1;
                s2[v] = n2;
            }
            y[v] = out;
        }
        const int done = t - (N - 1);
        if (done >= 0 && done < count) sink(done, y[V - 1][(N - 1) % 2]);
    };
    const int steps = count + N - 1;
    const int steady_end = count;  // steps N-1 ... count-1 have every lane in range
    int t = 0;
    for (; t < std::min(N - 1, steps); ++t) step(t < count ? input(t) : 0.0, true, t);
    for (; t < steady_end; ++t) step(input(t), false, t);
    for (; t < steps; ++t) step(0.0, true, t);
    for (std::ptrdiff_t v = 0; v < V; ++v) {
        const double first0 = s1[v][0], second0 = s2[v][0], first1 = s1[v][1], second1 = s2[v][1];
        sections[2 * v].set_state({first0, second0});
        if (2 * v + 1 < N) sections[2 * v + 1].set_state({first1, second1});
    }
}
}  // namespace detail

// For i < count, in increasing i: sink(i, the N sections in turn applied to input(i)), in
// double.
// Bit for bit the sections' own output where multiplies and adds are not fused (tactus builds
// with -ffp-contract=off, CMakeLists.txt): the wavefront then rounds as Biquad::process does.
template <int N, typename Input, typename Sink>
void cascade_each(Biquad* sections, int count, Input input, Sink sink) noexcept {
    if constexpr (N >= 2)
        detail::wavefront_each<N>(sections, count, input, sink);
    else
        detail::serial_each<N>(sections, count, input, sink);
}

namespace detail {
template <int N>
void run(Biquad* sections, float* samples, int count, double gain) noexcept {
    cascade_each<N>(
        sections, count, [&](int i) { return samples[i] * gain; },
        [&](int i, double y) { samples[i] = static_cast<float>(y); });
}

template <int... N>
constexpr auto cascade_table(std::integer_sequence<int, N...>) {
    return std::array{&run<N>...};
}
}  // namespace detail

// samples[i] = the first `size` sections in turn applied to gain * samples[i]; size <= 16.
inline void process_cascade(Biquad* sections, int size, float* samples, int count,
                            double gain = 1.0) noexcept {
    static constexpr auto kTable = detail::cascade_table(std::make_integer_sequence<int, 17>{});
    kTable[static_cast<size_t>(size)](sections, samples, count, gain);
}

}  // namespace tactus
