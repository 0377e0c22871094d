#include "tactus/analysis/brightness.hpp"

#include <cmath>

namespace tactus {

double spectral_centroid_hz(std::span<const float> magnitudes, double bin_hz) noexcept {
    constexpr double kSilentMagnitudeSum = 1e-9;
    double weighted_log = 0.0, total = 0.0;
    for (size_t k = 1; k < magnitudes.size(); ++k) {
        weighted_log += std::log(static_cast<double>(k)) * magnitudes[k];
        total += magnitudes[k];
    }
    return total > kSilentMagnitudeSum ? bin_hz * std::exp(weighted_log / total) : 0.0;
}

}  // namespace tactus
