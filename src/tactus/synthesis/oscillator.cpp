#include "tactus/synthesis/oscillator.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {
// 1 / k for the odd harmonics k = 1, 3, 5 ... 1023 (f0 down to ~1 Hz under a 1 kHz limit).
constexpr auto kOddReciprocals = [] {
    std::array<double, 512> table{};
    for (size_t i = 0; i < table.size(); ++i) table[i] = 1.0 / static_cast<double>(2 * i + 1);
    return table;
}();

// sin(2 pi phase) for phase in [0, 1): the quarter-cycle reduction is exact in cycles, then a
// Taylor polynomial of sin or cos on |x| <= pi/4 (truncation below 5e-17), evaluated by
// Estrin's scheme (independent pairs: half the dependent steps of Horner's rule). Agrees with
// std::sin(2 pi phase) to 1e-15 at a fraction of its cost.
double sin_of_cycles(double phase) noexcept {
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
    // 2 f0 below the limit, so partials enter and leave without clicks as f0 moves.
    const double two_cos = 2.0 - 4.0 * fundamental * fundamental;  // 2 cos 2x = 2 - 4 sin^2 x
    double previous = -fundamental, current = fundamental;         // sin(-x), sin(x)
    double square = 0.0;
    constexpr double kMostHarmonics = 1e5;  // bounds the loop for absurdly low f0
    const int last_harmonic =
        std::max(1, static_cast<int>(std::min(harmonic_limit_hz_ / frequency_hz, kMostHarmonics)));
    const double fade_per_hz = 0.5 / frequency_hz;  // multiplications: no division per harmonic
    const auto next = [&] {
        const double next_harmonic = two_cos * current - previous;
        previous = current;
        current = next_harmonic;
    };
    square += current;  // k = 1: weight 1 and 1 / k = 1, both products exact
    next();
    // The harmonics with a tabled reciprocal, then (absurdly low f0) the others.
    const int last_tabled =
        std::min(last_harmonic, static_cast<int>(2 * kOddReciprocals.size() - 1));
    int k = 3;
    for (; k <= last_tabled; k += 2) {
        const double weight = std::min(1.0, (harmonic_limit_hz_ - k * frequency_hz) * fade_per_hz);
        square += weight * current * kOddReciprocals[static_cast<size_t>(k / 2)];
        next();
    }
    for (; k <= last_harmonic; k += 2) {
        const double weight = std::min(1.0, (harmonic_limit_hz_ - k * frequency_hz) * fade_per_hz);
        square += weight * current * (1.0 / k);
        next();
    }
    square *= 4.0 / kPi;
    return fundamental + square_mix * (square - fundamental);
}

}  // namespace tactus
