#include "tactus/analysis/noisiness.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "tactus/core/fast_math.hpp"
#include "tactus/core/vector_clones.hpp"

namespace tactus {
namespace {
// Critical band edges in Hz (Zwicker 1961, Table 1).
constexpr std::array<double, 25> kBarkEdgesHz = {
    0,    100,  200,  300,  400,  510,  630,  770,  920,  1080, 1270,  1480, 1720,
    2000, 2320, 2700, 3150, 3700, 4400, 5300, 6400, 7700, 9500, 12000, 15500};
constexpr double kSilentPower = 1e-14;
}  // namespace

void Noisiness::prepare(int bins, double bin_hz) {
    bands_.clear();
    for (size_t b = 0; b + 1 < kBarkEdgesHz.size(); ++b) {
        const int first = std::max(1, static_cast<int>(std::ceil(kBarkEdgesHz[b] / bin_hz)));
        const int end = std::min(bins, static_cast<int>(std::ceil(kBarkEdgesHz[b + 1] / bin_hz)));
        if (end > first) bands_.push_back({first, end});
    }
}

TACTUS_VECTOR_CLONES double Noisiness::compute(std::span<const float> powers) const noexcept {
    if (bands_.empty()) return 0.0;
    // The logarithm of the densities' product, taken every kProductBands bands: one library
    // log where each band took one. A density lies in [kSilentPower, 1e11] (the input at
    // kMaxInputLevel), so the product of kProductBands stays well inside a double's range.
    constexpr int kProductBands = 8;
    double log_sum = 0.0, product = 1.0, sum = 0.0;
    int in_product = 0;
    for (const Band& band : bands_) {
        const double power = sum_of(powers.data() + band.first_bin, band.end_bin - band.first_bin);
        const double density = power / (band.end_bin - band.first_bin) + kSilentPower;
        product *= density;
        sum += density;
        if (++in_product == kProductBands) {
            log_sum += std::log(product);
            product = 1.0;
            in_product = 0;
        }
    }
    log_sum += std::log(product);
    const double n = static_cast<double>(bands_.size());
    const double arithmetic = sum / n;
    if (arithmetic <= 2 * kSilentPower) return 0.0;
    return std::clamp(std::exp(log_sum / n) / arithmetic, 0.0, 1.0);
}

}  // namespace tactus
