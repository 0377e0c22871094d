#include "tactus/analysis/loudness.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tactus {
namespace {

// BS.1770-4 K-weighting analogue parameters (the 48 kHz coefficients of the standard
// re-expressed as frequency, gain and Q; libebur128, ebur128.c).
constexpr double kShelfHz = 1681.974450955533;
constexpr double kShelfGainDb = 3.999843853973347;
constexpr double kShelfQ = 0.7071752369554196;
constexpr double kHighpassHz = 38.13547087602444;
constexpr double kHighpassQ = 0.5003270373238773;
constexpr double kLkfsOffsetDb = -0.691;  // BS.1770-4 eq. 2

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

void Loudness::prepare(const ProcessSpec& spec, double window_ms) {
    const double sample_rate_hz = spec.sample_rate_hz;
    shelf_.set(k_shelf(sample_rate_hz));
    highpass_.set(k_highpass(sample_rate_hz));
    const auto length = std::max<int64_t>(1, ms_to_samples(window_ms, sample_rate_hz));
    squares_.assign(static_cast<size_t>(length), 0.0);
    reset();
}

void Loudness::reset() noexcept {
    shelf_.reset();
    highpass_.reset();
    std::fill(squares_.begin(), squares_.end(), 0.0);
    position_ = 0;
    sum_ = 0.0;
}

void Loudness::process(const float* samples, int count) noexcept {
    const size_t length = squares_.size();
    Biquad shelf = shelf_, highpass = highpass_;  // state in locals: kept in registers
    double sum = sum_;
    size_t position = position_;
    for (int i = 0; i < count; ++i) {
        const double y = highpass.process(shelf.process(samples[i]));
        sum += y * y - squares_[position];
        squares_[position] = y * y;
        if (++position == length) {  // re-sum once per window: no rounding drift
            position = 0;
            sum = std::accumulate(squares_.begin(), squares_.end(), 0.0);
        }
    }
    shelf_ = shelf;
    highpass_ = highpass;
    sum_ = sum;
    position_ = position;
}

double Loudness::loudness_db() const noexcept {
    const double mean_square = std::max(0.0, sum_) / static_cast<double>(squares_.size());
    if (mean_square <= 1e-12) return kFloorDb;
    return std::max(kFloorDb, kLkfsOffsetDb + power_to_db(mean_square));
}

}  // namespace tactus
