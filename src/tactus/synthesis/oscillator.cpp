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
}  // namespace

void Oscillator::prepare(double sample_rate_hz, double harmonic_limit_hz) {
    sample_rate_hz_ = sample_rate_hz;
    harmonic_limit_hz_ = std::min(harmonic_limit_hz, 0.45 * sample_rate_hz);
    reset();
}

double Oscillator::next(double frequency_hz, double square_mix) noexcept {
    if (!std::isfinite(frequency_hz)) frequency_hz = 0.0;  // never let NaN into the phase
    const double angle = 2.0 * kPi * phase_;
    phase_ += frequency_hz / sample_rate_hz_;
    phase_ -= std::floor(phase_);

    const double fundamental = std::sin(angle);
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
    for (int k = 1; k <= last_harmonic; k += 2) {
        const double weight =
            k == 1 ? 1.0 : std::min(1.0, (harmonic_limit_hz_ - k * frequency_hz) * fade_per_hz);
        const auto odd = static_cast<size_t>(k / 2);
        square +=
            weight * current * (odd < kOddReciprocals.size() ? kOddReciprocals[odd] : 1.0 / k);
        const double next_harmonic = two_cos * current - previous;
        previous = current;
        current = next_harmonic;
    }
    square *= 4.0 / kPi;
    return fundamental + square_mix * (square - fundamental);
}

}  // namespace tactus
