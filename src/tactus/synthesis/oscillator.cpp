#include "tactus/synthesis/oscillator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {
// 1 / k for the odd harmonics k = 1, 3, 5 ... 1023: every harmonic of f0 down to ~1 Hz under a
// 1 kHz limit, the series' length below that.
constexpr auto kOddReciprocals = [] {
    std::array<double, 512> table{};
    for (size_t i = 0; i < table.size(); ++i) table[i] = 1.0 / static_cast<double>(2 * i + 1);
    return table;
}();

// sin(2 pi phase) for phase in [0, 1): the quarter-cycle reduction is exact in cycles, then a
// Taylor polynomial of sin or cos on |x| <= pi/4 (truncation below 5e-17), evaluated by
// Estrin's scheme. Agrees with std::sin(2 pi phase) to 1e-15; fills the table below.
constexpr double taylor_sin_of_cycles(double phase) noexcept {
    // NOLINTNEXTLINE(bugprone-incorrect-roundings): phase >= 0; lround could move a rounding
    const auto quadrant = static_cast<int>(4.0 * phase + 0.5);  // nearest quarter, 0 ... 4
    const double x = 2.0 * kPi * (phase - 0.25 * quadrant);
    const double z = x * x, z2 = z * z, z4 = z2 * z2;
    if (quadrant % 2 == 0) {  // x (1 - z/3! + z^2/5! - ... - z^7/15!)
        const double p01 = 1.0 - z * (1.0 / 6), p23 = 1.0 / 120 - z * (1.0 / 5040);
        const double p45 = 1.0 / 362880 - z * (1.0 / 39916800);
        const double p67 = 1.0 / 6227020800 - z * (1.0 / 1307674368000);
        const double s = x * ((p01 + z2 * p23) + z4 * (p45 + z2 * p67));
        return quadrant == 2 ? -s : s;
    }
    // 1 - z/2! + z^2/4! - ... + z^8/16!
    const double p01 = 1.0 - z * (1.0 / 2), p23 = 1.0 / 24 - z * (1.0 / 720);
    const double p45 = 1.0 / 40320 - z * (1.0 / 3628800);
    const double p67 = 1.0 / 479001600 - z * (1.0 / 87178291200);
    const double c = (p01 + z2 * p23) + z4 * ((p45 + z2 * p67) + z4 * (1.0 / 20922789888000));
    return quadrant == 3 ? -c : c;
}

// sin(2 pi j / kSteps) for j = 0 ... kSteps + kSteps / 4: the sine and (a quarter cycle on)
// the cosine of every step of the cycle, both ends included.
constexpr int kSteps = 512;
constexpr auto kSines = [] {
    std::array<double, kSteps + kSteps / 4 + 1> table{};
    for (size_t j = 0; j < table.size(); ++j) {
        const double cycles = static_cast<double>(j) / kSteps;
        table[j] = taylor_sin_of_cycles(cycles < 1.0 ? cycles : cycles - 1.0);
    }
    return table;
}();

// sin(2 pi phase) for phase in [0, 1), from the nearest step j and the remainder b (|b| <= pi /
// kSteps, exact in cycles): sin(a + b) = sin a cos b + cos a sin b, with short Taylor
// polynomials of b (truncation below 1e-19). Within a few 1e-16 of std::sin(2 pi phase), at
// half the cost of the polynomial on a quarter cycle.
double sin_of_cycles(double phase) noexcept {
    const double steps = phase * kSteps;
    // NOLINTNEXTLINE(bugprone-incorrect-roundings): phase >= 0; lround could move a rounding
    const auto j = static_cast<int>(steps + 0.5);  // nearest step, 0 ... kSteps
    const double b = (steps - j) * (2.0 * kPi / kSteps);
    const double z = b * b;
    const double sin_b = b + b * (z * (-1.0 / 6 + z * (1.0 / 120)));
    const double cos_b = 1.0 + z * (-0.5 + z * (1.0 / 24));
    const auto at = static_cast<size_t>(j);
    return kSines[at] * cos_b + kSines[at + kSteps / 4] * sin_b;
}
}  // namespace

void Oscillator::prepare(const ProcessSpec& spec, double harmonic_limit_hz) {
    const double sample_rate_hz = spec.sample_rate_hz;
    sample_rate_hz_ = sample_rate_hz;
    harmonic_limit_hz_ = std::min(harmonic_limit_hz, 0.45 * sample_rate_hz);
    reset();
}

double Oscillator::next(double frequency_hz, double square_mix) noexcept {
    if (!std::isfinite(frequency_hz)) frequency_hz = 0.0;  // never let NaN into the phase
    const double fundamental = sin_of_cycles(phase_);
    phase_ += frequency_hz / sample_rate_hz_;
    // phase - floor(phase): below 2 cycles (any f0 under the rate) a comparison does it exactly.
    if (phase_ >= 1.0 && phase_ < 2.0)
        phase_ -= 1.0;
    else if (!(phase_ >= 0.0 && phase_ < 1.0))
        phase_ -= std::floor(phase_);

    if (!(square_mix > 0.0 && frequency_hz > 0.0)) return fundamental;

    // Odd harmonics below the limit; each above the fundamental fades in linearly over the last
    // 2 f0 below the limit, so partials enter and leave without clicks as f0 moves: harmonic k
    // weighs min(1, (limit - k f0) / (2 f0)) = min(1, (ratio - k) / 2), ratio = limit / f0. Only
    // the last odd harmonic up to the limit weighs less than 1.
    const double two_cos = 2.0 - 4.0 * fundamental * fundamental;  // 2 cos 2x = 2 - 4 sin^2 x
    // Up to the tabled harmonics: under limit / 1024 (about 1 Hz) the series stops at 1023 f0,
    // its last harmonic at half weight, still band-limited.
    constexpr double kMostHarmonics = 2.0 * kOddReciprocals.size();
    const double ratio = std::min(harmonic_limit_hz_ / frequency_hz, kMostHarmonics);
    const auto last_harmonic = static_cast<int>(ratio);  // 0 for an f0 above the limit
    const int top = (last_harmonic - 1) | 1;             // the last odd harmonic
    double square = fundamental;                         // k = 1: weight 1 and 1 / k = 1
    // No harmonic above the fundamental: the loops below would add nothing.
    if (top < 3) return fundamental + square_mix * (square * (4.0 / kPi) - fundamental);
    // sin kx and sin (k+2)x, from harmonic k = 3 on
    double lane0 = two_cos * fundamental + fundamental, lane1 = two_cos * lane0 - fundamental;
    int k = 3;
    // Four full-weight harmonics a turn: two recurrences of stride 4 side by side in one vector
    // of two, sin((k+4)x) = 2 cos(4x) sin(kx) - sin((k-4)x) in each lane, `before` and `lanes`
    // trading places so no value is moved. The compiler's generic vectors: one SIMD instruction
    // for both lanes where the target has them, two scalar ones where not. The lowest pulses,
    // whose squares have the most harmonics (ten odd ones for 45 Hz under 1 kHz), set the p99
    // block's cost.
    const int last_full = top - 2;
    if (k + 6 <= last_full) {
        using Pair = double __attribute__((vector_size(2 * sizeof(double))));
        const auto reciprocals = [](size_t i) {  // 1 / k, 1 / (k+2) for k = 2 i + 1
            Pair r;
            std::memcpy(&r, &kOddReciprocals[i], sizeof r);
            return r;
        };
        const double two_cos4 = two_cos * two_cos - 2.0;  // 2 cos 4x = (2 cos 2x)^2 - 2
        Pair lanes = {lane0, lane1}, before = {-fundamental, fundamental};  // k, k+2; k-4, k-2
        Pair sums = {0.0, 0.0};
        const auto last_index = static_cast<size_t>(last_full / 2);
        size_t i = 1;  // harmonic k = 2 i + 1
        for (; i + 3 <= last_index; i += 4) {
            sums += lanes * reciprocals(i);
            before = two_cos4 * lanes - before;  // the next two harmonics, in `before`
            sums += before * reciprocals(i + 2);
            lanes = two_cos4 * before - lanes;
        }
        if (i + 1 <= last_index) {  // two more
            sums += lanes * reciprocals(i);
            lanes = two_cos4 * lanes - before;
            i += 2;
        }
        square += sums[0] + sums[1];
        k = 2 * static_cast<int>(i) + 1;
        lane0 = lanes[0];
        lane1 = lanes[1];
    }
    const auto reciprocal = [](int harmonic) {
        return kOddReciprocals[static_cast<size_t>(harmonic / 2)];
    };
    // The rest at full weight but the last two, one at a time: none after the turns, one for a
    // top of 7, two for 9.
    for (; k + 2 < top; k += 2) {
        square += lane0 * reciprocal(k);
        const double next_harmonic = two_cos * lane1 - lane0;
        lane0 = lane1;
        lane1 = next_harmonic;
    }
    // The last one or two: top - 2 at full weight, then top, weighted.
    const double top_weight = std::min(1.0, 0.5 * (ratio - top));
    if (k == top)
        square += top_weight * lane0 * reciprocal(k);
    else
        square += lane0 * reciprocal(k) + top_weight * lane1 * reciprocal(k + 2);
    square *= 4.0 / kPi;
    return fundamental + square_mix * (square - fundamental);
}

}  // namespace tactus
