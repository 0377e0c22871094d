// A cascade of biquads run over a block, its output given sample by sample to a sink (a band's
// energy, a K-weighted square) or written back (process_cascade). The sections are copied into
// locals of a size fixed at compile time, so the compiler unrolls the section loop and keeps the
// states in registers. Two or more sections also run in a wavefront (where the compiler does not
// fuse multiply-adds), two or four per vector: at step t, section k filters sample t - k, so all
// sections advance at once instead of one after the other. Each section does exactly
// Biquad::process's arithmetic on every sample, in the same order: the output is bit-identical to
// applying the sections in turn, for any block split.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "tactus/core/vector_clones.hpp"
#include "tactus/dsp/biquad.hpp"

namespace tactus {

namespace detail {
// A lane's sample index in a masked step (whether 0 <= index < count selects the lane), as wide
// as the lanes' doubles, so that a comparison's mask selects whole lanes.
using LaneIndexPair = long long __attribute__((vector_size(2 * sizeof(long long))));
using LaneIndexQuad = long long __attribute__((vector_size(4 * sizeof(long long))));
// Whether masked steps select their lanes with a vector mask (x86-64), or store lane by lane.
// Counted on a 64-frame block (bench/results.md): the mask saves 0.3 M instructions a second on
// x86-64 (AVX2), and costs 8 % more a block on arm64 and 24 % on armhf, whose 64-bit lane
// comparisons and selects are split into scalar operations.
#if defined(__x86_64__)
inline constexpr bool kMaskedSelect = true;
#else
inline constexpr bool kMaskedSelect = false;
#endif

// A masked step's states: the lanes whose sample t - place lies in the block (0 <= t - place <
// count) take the new states n1, n2; the others keep theirs. By reference: inlined into the
// vector clones, never passed as a 32-byte vector.
template <typename Lanes, typename Places>
inline void update_live_lanes(Lanes& s1, Lanes& s2, const Lanes& n1, const Lanes& n2,
                              const Places& place, int t, int count) noexcept {
    if constexpr (kMaskedSelect) {
        const Places at = t - place;
        const Places live = (at >= 0) & (at < count);
        s1 = live ? n1 : s1;
        s2 = live ? n2 : s2;
    } else {
        for (int lane = 0; lane < static_cast<int>(sizeof(Lanes) / sizeof(double)); ++lane) {
            const int at = t - static_cast<int>(place[lane]);
            if (at >= 0 && at < count) s1[lane] = n1[lane], s2[lane] = n2[lane];
        }
    }
}

// One step of the sections in a vector of lanes, each Biquad::process's arithmetic in its order
// on its input x: their outputs into y, their new states into s1 and s2, every lane's or
// (`masked`) the live lanes' only. By reference, as update_live_lanes.
template <typename Lanes, typename Places>
[[gnu::always_inline]] inline void step_sections(const Lanes& b0, const Lanes& b1, const Lanes& b2,
                                                 const Lanes& a1, const Lanes& a2, Lanes& s1,
                                                 Lanes& s2, Lanes& y, const Lanes& x, bool masked,
                                                 const Places& place, int t, int count) noexcept {
    const Lanes out = b0 * x + s1;
    const Lanes n1 = (b1 * x - a1 * out) + s2;
    const Lanes n2 = b2 * x - a2 * out;
    if (masked) {
        update_live_lanes(s1, s2, n1, n2, place, t, count);
    } else {
        s1 = n1;
        s2 = n2;
    }
    y = out;
}

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

// cascade_each in a wavefront, kLanes sections per vector: four for cascades of three or more
// sections, two for two (the compiler's generic vectors: one AVX2 vector or two SSE2 ones on
// x86-64, where the function is cloned for AVX2; two NEON vectors on arm64; pairs of scalars
// where the target has no double vectors).
template <int N, typename Input, typename Sink>
TACTUS_VECTOR_CLONES void wavefront_each(Biquad* sections, int count, Input input,
                                         Sink sink) noexcept {
    using Pair = double __attribute__((vector_size(2 * sizeof(double))));
    using Quad = double __attribute__((vector_size(4 * sizeof(double))));
    using Lanes = std::conditional_t<(N > 2), Quad, Pair>;
    constexpr int kLanes = sizeof(Lanes) / sizeof(double);
    constexpr int V = (N + kLanes - 1) / kLanes;  // spare lanes are pass-throughs
    using Places = std::conditional_t<(N > 2), LaneIndexQuad, LaneIndexPair>;
    Places place[V];  // lane k holds section k: it filters sample t - k at step t
    for (int k = 0; k < V * kLanes; ++k) place[k / kLanes][k % kLanes] = k;
    Lanes b0[V], b1[V], b2[V], a1[V], a2[V], s1[V], s2[V], y[V];
    for (int v = 0; v < V; ++v) {
        for (int lane = 0; lane < kLanes; ++lane) {
            const int k = kLanes * v + lane;
            const BiquadCoefficients pass{};
            const BiquadCoefficients& c = k < N ? sections[k].coefficients() : pass;
            const auto state = k < N ? sections[k].state() : std::pair{0.0, 0.0};
            b0[v][lane] = c.b0, b1[v][lane] = c.b1, b2[v][lane] = c.b2;
            a1[v][lane] = c.a1, a2[v][lane] = c.a2;
            s1[v][lane] = state.first, s2[v][lane] = state.second;
            y[v][lane] = 0.0;
        }
    }
    // One step: every lane takes its left neighbour's last output (lane 0 the new sample); the
    // vectors go from the last, so each still reads its left neighbour's previous output.
    // Lanes outside 0 <= t - k < count keep their state (`masked`).
    auto step = [&](double input, bool masked, int t) {
        for (int v = V - 1; v >= 0; --v) {
            const double first = v == 0 ? input : y[v - 1][kLanes - 1];
            Lanes x;
            if constexpr (kLanes == 4)
                x = Lanes{first, y[v][0], y[v][1], y[v][2]};
            else
                x = Lanes{first, y[v][0]};
            step_sections(b0[v], b1[v], b2[v], a1[v], a2[v], s1[v], s2[v], y[v], x, masked,
                          place[v], t, count);
        }
        const int done = t - (N - 1);  // unmasked steps all have 0 <= done < count
        if (!masked || (done >= 0 && done < count)) sink(done, y[V - 1][(N - 1) % kLanes]);
    };
    const int steps = count + N - 1;
    const int steady_end = count;  // steps N-1 ... count-1 have every lane in range
    int t = 0;
    for (; t < std::min(N - 1, steps); ++t) step(t < count ? input(t) : 0.0, true, t);
    for (; t < steady_end; ++t) step(input(t), false, t);
    for (; t < steps; ++t) step(0.0, true, t);
    for (int k = 0; k < N; ++k) {
        const double first = s1[k / kLanes][k % kLanes], second = s2[k / kLanes][k % kLanes];
        sections[k].set_state({first, second});
    }
}

// The lanes of cascades side by side (cascades_each): chain c's sections in lanes
// start[c] ... start[c] + Lengths[c] - 1, four lanes a vector.
template <int... Lengths>
struct SideBySide {
    static constexpr int kChains = sizeof...(Lengths);
    static constexpr std::array<int, kChains> kLength{Lengths...};
    static constexpr int kSections = (Lengths + ...);
    static constexpr int kLongest = std::max({Lengths...});
    static constexpr int kLanes = 4;
    static constexpr int kVectors = (kSections + kLanes - 1) / kLanes;
    static constexpr int kSlots = kVectors * kLanes;
    // Per lane: its chain (-1: a spare lane) and its place in it (0: the chain's head).
    static constexpr std::array<int, kSlots> kChain = [] {
        std::array<int, kSlots> chain{};
        for (int k = 0; k < kSlots; ++k) chain[k] = -1;
        for (int c = 0, k = 0; c < kChains; ++c)
            for (int p = 0; p < kLength[c]; ++p) chain[k++] = c;
        return chain;
    }();
    static constexpr std::array<int, kSlots> kPlace = [] {
        std::array<int, kSlots> place{};
        for (int c = 0, k = 0; c < kChains; ++c)
            for (int p = 0; p < kLength[c]; ++p) place[k++] = p;
        return place;
    }();
};

// side_by_side_each's lanes: chain c's sections in lanes start[c] ..., spare lanes passing their
// input through; the coefficients and the states. Aligned as the AVX2 clones load them: without
// AVX a 32-byte vector type is only 16-byte aligned (GCC caps it at the target's largest), and
// an object placed by that alignment faults in a clone's aligned loads.
template <int... Lengths>
struct alignas(4 * sizeof(double)) LanesOf {
    using Layout = SideBySide<Lengths...>;
    using Lanes = double __attribute__((vector_size(4 * sizeof(double))));  // Layout::kLanes
    static constexpr int V = Layout::kVectors;
    Lanes b0[V], b1[V], b2[V], a1[V], a2[V], s1[V], s2[V];

    // Chains: an array of kChains pointers to Biquad, const or not.
    template <typename Chains>
    void load(const Chains& chains) noexcept {
        for (int k = 0; k < Layout::kSlots; ++k) {
            const int v = k / Layout::kLanes, lane = k % Layout::kLanes, c = Layout::kChain[k];
            const BiquadCoefficients pass{};
            const Biquad* section = c >= 0 ? chains[c] + Layout::kPlace[k] : nullptr;
            const BiquadCoefficients& co = section ? section->coefficients() : pass;
            const auto state = section ? section->state() : std::pair{0.0, 0.0};
            b0[v][lane] = co.b0, b1[v][lane] = co.b1, b2[v][lane] = co.b2;
            a1[v][lane] = co.a1, a2[v][lane] = co.a2;
            s1[v][lane] = state.first, s2[v][lane] = state.second;
        }
    }
    void store_states(const std::array<Biquad*, Layout::kChains>& chains) const noexcept {
        for (int k = 0; k < Layout::kSlots; ++k) {
            const int v = k / Layout::kLanes, lane = k % Layout::kLanes, c = Layout::kChain[k];
            if (c >= 0) chains[c][Layout::kPlace[k]].set_state({s1[v][lane], s2[v][lane]});
        }
    }
};

// cascades_each's work on the lanes: wavefront_each with a head lane per chain.
template <int... Lengths, typename Input, typename Sink>
TACTUS_VECTOR_CLONES Sink side_by_side_each(LanesOf<Lengths...>& lanes, int count, Input input,
                                            Sink sink) noexcept {
    using Layout = SideBySide<Lengths...>;
    using Lanes = typename LanesOf<Lengths...>::Lanes;
    constexpr int kLanes = Layout::kLanes, V = Layout::kVectors, C = Layout::kChains;
    // Each lane's place in its chain: it filters sample t - place at step t.
    LaneIndexQuad place[V];
    for (int k = 0; k < Layout::kSlots; ++k) place[k / kLanes][k % kLanes] = Layout::kPlace[k];
    // In locals for the block: kept in registers.
    Lanes b0[V], b1[V], b2[V], a1[V], a2[V], s1[V], s2[V], y[V];
    for (int v = 0; v < V; ++v) {
        b0[v] = lanes.b0[v], b1[v] = lanes.b1[v], b2[v] = lanes.b2[v];
        a1[v] = lanes.a1[v], a2[v] = lanes.a2[v];
        s1[v] = lanes.s1[v], s2[v] = lanes.s2[v];
        y[v] = Lanes{};
    }
    // One step: each chain's head takes its new sample, every other lane its left neighbour's
    // last output (the vectors go from the last, so each still reads its neighbour's previous
    // output); lanes outside 0 <= t - place < count keep their state (`masked`).
    auto step = [&](const std::array<double, C>& in, bool masked, int t) {
        for (int v = V - 1; v >= 0; --v) {
            Lanes x;
            for (int lane = 0; lane < kLanes; ++lane) {
                const int k = v * kLanes + lane, c = Layout::kChain[k];
                if (c < 0)
                    x[lane] = 0.0;
                else if (Layout::kPlace[k] == 0)
                    x[lane] = in[c];
                else  // a section after a chain's head: lane k - 1 holds the one before it
                    x[lane] = y[std::max(k - 1, 0) / kLanes][std::max(k - 1, 0) % kLanes];
            }
            step_sections(b0[v], b1[v], b2[v], a1[v], a2[v], s1[v], s2[v], y[v], x, masked,
                          place[v], t, count);
        }
        for (int c = 0, last = -1; c < C; ++c) {
            last += Layout::kLength[c];
            const int done = t - (Layout::kLength[c] - 1);  // as in wavefront_each
            if (!masked || (done >= 0 && done < count))
                sink(c, done, y[last / kLanes][last % kLanes]);
        }
    };
    const auto inputs = [&](int t) {
        std::array<double, C> in{};
        if (t < count)
            for (int c = 0; c < C; ++c) in[c] = input(c, t);
        return in;
    };
    const int steps = count + Layout::kLongest - 1;
    int t = 0;
    for (; t < std::min(Layout::kLongest - 1, steps); ++t) step(inputs(t), true, t);
    for (; t < count; ++t) step(inputs(t), false, t);
    for (; t < steps; ++t) step(inputs(t), true, t);
    for (int v = 0; v < V; ++v) lanes.s1[v] = s1[v], lanes.s2[v] = s2[v];
    return sink;
}
}  // namespace detail

// Independent cascades side by side, chain c of Lengths[c] sections (chains[c][0 ...]): for
// i < count, in increasing i for each chain, sink(c, i, chain c applied to input(c, i)), in
// double; chains of one length in chain order at each i (a longer chain's output comes its extra
// sections' steps later). One wavefront carries them all, so they advance together instead of
// one after the other (a biquad's recursion, more than its arithmetic, bounds a cascade's
// speed). Bit for bit each chain's own cascade_each.
// Returns the sink, as std::for_each returns its function: a sink that carries its sums by value
// keeps them in registers.
template <int... Lengths, typename Input, typename Sink>
Sink cascades_each(const std::array<Biquad*, sizeof...(Lengths)>& chains, int count, Input input,
                   Sink sink) noexcept {
    detail::LanesOf<Lengths...> lanes;
    lanes.load(chains);
    Sink done = detail::side_by_side_each(lanes, count, input, sink);
    lanes.store_states(chains);
    return done;
}

// Chains of biquads side by side as cascades_each runs them, laid out in its lanes once and kept
// there from block to block: for filters that run on every block (the analysis's input filters,
// analyzer.cpp), a block neither gathers their coefficients and states nor scatters the states.
// Bit for bit cascades_each on the chains the lanes were loaded from.
template <int... Lengths>
class CascadeLanes {
  public:
    // The chains' coefficients and states, copied (prepare()).
    void load(const std::array<const Biquad*, sizeof...(Lengths)>& chains) noexcept {
        lanes_.load(chains);
    }
    void reset() noexcept {
        using Lanes = typename detail::LanesOf<Lengths...>::Lanes;
        for (int v = 0; v < detail::LanesOf<Lengths...>::V; ++v)
            lanes_.s1[v] = lanes_.s2[v] = Lanes{};
    }
    // cascades_each on the lanes.
    template <typename Input, typename Sink>
    Sink each(int count, Input input, Sink sink) noexcept {
        return detail::side_by_side_each(lanes_, count, input, sink);
    }

  private:
    detail::LanesOf<Lengths...> lanes_;
};

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
