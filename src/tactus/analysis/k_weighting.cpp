#include "tactus/analysis/k_weighting.hpp"

#include <array>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {
// BS.1770-4 K-weighting analogue parameters (the 48 kHz coefficients of the standard
// re-expressed as frequency, gain and Q; libebur128, ebur128.c).
constexpr double kShelfHz = 1681.974450955533;
constexpr double kShelfGainDb = 3.999843853973347;
constexpr double kShelfQ = 0.7071752369554196;
constexpr double kHighpassHz = 38.13547087602444;
constexpr double kHighpassQ = 0.5003270373238773;

BiquadCoefficients k_shelf(double fs) {
    const double k = std::tan(kPi * kShelfHz / fs);
    const double vh = std::pow(10.0, kShelfGainDb / 20.0);
    const double vb = std::pow(vh, 0.4996667741545416);
    const double a0 = 1.0 + k / kShelfQ + k * k;
    return {(vh + vb * k / kShelfQ + k * k) / a0, 2.0 * (k * k - vh) / a0,
            (vh - vb * k / kShelfQ + k * k) / a0, 2.0 * (k * k - 1.0) / a0,
            (1.0 - k / kShelfQ + k * k) / a0};
}

BiquadCoefficients k_highpass(double fs) {
    const double k = std::tan(kPi * kHighpassHz / fs);
    const double a0 = 1.0 + k / kHighpassQ + k * k;
    return {1.0, -2.0, 1.0, 2.0 * (k * k - 1.0) / a0, (1.0 - k / kHighpassQ + k * k) / a0};
}
}  // namespace

void KWeighting::prepare(const ProcessSpec& spec) {
    sections_[0].set(k_shelf(spec.sample_rate_hz));
    sections_[1].set(k_highpass(spec.sample_rate_hz));
    reset();
}

void KWeighting::add_power(const float* samples, float* power, int count) noexcept {
    each(samples, count, [&](int i, double y) { power[i] += static_cast<float>(y * y); });
}

void KWeighting::add_power(KWeighting& a, const float* a_samples, KWeighting& b,
                           const float* b_samples, float* power, int count) noexcept {
    const std::array<const float*, 2> samples{a_samples, b_samples};
    cascades_each<2, 2>(
        {a.sections_.data(), b.sections_.data()}, count,
        [&](int c, int i) { return static_cast<double>(samples[c][i]); },
        [&](int, int i, double y) { power[i] += static_cast<float>(y * y); });
}

}  // namespace tactus
