#include "tactus/analysis/loudness.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {
constexpr double kLkfsOffsetDb = -0.691;  // BS.1770-4 eq. 2
}  // namespace

void Loudness::prepare(const ProcessSpec& spec, double window_ms) {
    const double sample_rate_hz = spec.sample_rate_hz;
    k_weighting_.prepare(spec);
    const auto length = std::max<int64_t>(1, ms_to_samples(window_ms, sample_rate_hz));
    squares_.assign(static_cast<size_t>(length), 0.0);
    reset();
}

void Loudness::reset() noexcept {
    k_weighting_.reset();
    std::fill(squares_.begin(), squares_.end(), 0.0);
    position_ = 0;
    sum_ = fresh_sum_ = 0.0;
}

void Loudness::close(const Squares& squares) noexcept {
    position_ = squares.position;
    sum_ = squares.sum;
    fresh_sum_ = squares.fresh;
}

void Loudness::process(const float* samples, int count) noexcept {
    Squares squares = open();  // a local copy: kept in registers
    k_weighting_.each(samples, count, [&](int, double y) { squares.take(y * y); });
    close(squares);
}

void Loudness::process_power(const float* power, int count) noexcept {
    Squares squares = open();
    for (int i = 0; i < count; ++i) squares.take(static_cast<double>(power[i]));
    close(squares);
}

double Loudness::mean_square() const noexcept {
    return std::max(0.0, sum_) / static_cast<double>(squares_.size());
}

double Loudness::db_of(double mean_square) noexcept {
    if (mean_square <= 1e-12) return kFloorDb;
    return std::max(kFloorDb, kLkfsOffsetDb + power_to_db(mean_square));
}

}  // namespace tactus
