#include "tactus/analysis/brightness.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/fast_math.hpp"
#include "tactus/core/vector_clones.hpp"

namespace tactus {

void Brightness::prepare(int bins, double bin_hz, double max_hz) {
    log_bin_.resize(static_cast<size_t>(std::max(0, bins - 1)));
    for (size_t k = 0; k < log_bin_.size(); ++k) log_bin_[k] = std::log(static_cast<double>(k + 1));
    bin_hz_ = bin_hz;
    set_max_hz(max_hz);
}

void Brightness::set_max_hz(double max_hz) noexcept {
    const double bins = std::floor(max_hz / bin_hz_);
    counted_ = static_cast<int>(std::clamp(bins, 1.0, static_cast<double>(log_bin_.size())));
}

TACTUS_VECTOR_CLONES double Brightness::centroid_hz(
    std::span<const float> magnitudes) const noexcept {
    constexpr double kSilentMagnitudeSum = 1e-9;
    const int n = std::min(counted_, static_cast<int>(magnitudes.size()) - 1);
    const double total = sum_of(magnitudes.data() + 1, n);
    const double weighted_log = dot(log_bin_.data(), magnitudes.data() + 1, n);
    return total > kSilentMagnitudeSum ? bin_hz_ * std::exp(weighted_log / total) : 0.0;
}

}  // namespace tactus
