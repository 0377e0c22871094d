#include "tactus/analysis/brightness.hpp"

namespace tactus {

double spectral_centroid_hz(std::span<const float> magnitudes, double bin_hz) noexcept {
    constexpr double kSilentMagnitudeSum = 1e-9;
    double weighted = 0.0, total = 0.0;
    for (size_t k = 1; k < magnitudes.size(); ++k) {
        weighted += static_cast<double>(k) * magnitudes[k];
        total += magnitudes[k];
    }
    return total > kSilentMagnitudeSum ? bin_hz * weighted / total : 0.0;
}

}  // namespace tactus
