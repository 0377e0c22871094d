#include "tactus/analysis/part_features.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/analysis/band_power.hpp"
#include "tactus/core/fast_math.hpp"
#include "tactus/core/vector_clones.hpp"

namespace tactus {
namespace {
constexpr double kLowestHz = 40;
// The analysis spectrum's top: the resampler's pass band (analysis/analyzer.hpp).
constexpr double kTopHz = 5600;
// Shares below 1e-4 (-40 dB) all read as that: the bands' floor, not the bed's noise.
constexpr double kShareFloor = 1e-4;
constexpr double kRiseLimit = 3;      // log10 of added over bed power, either way
constexpr float kTinyPower = 1e-20f;  // keeps the logarithm of an empty bin finite

double log_share(double part, double total) {
    return std::log10(part / total + kShareFloor);
}
}  // namespace

void PartFeatures::prepare(SpectrumShape fast, SpectrumShape fine) {
    const auto bin_of = [](SpectrumShape s, double hz) {
        return std::clamp(static_cast<int>(std::ceil(hz / s.bin_hz)), 1, s.bins);
    };
    const double top_hz = std::min(kTopHz, fine.bin_hz * (fine.bins - 1));
    for (int b = 0; b <= kFineBands; ++b)
        fine_edges_[static_cast<size_t>(b)] =
            bin_of(fine, kLowestHz * std::pow(top_hz / kLowestHz, double(b) / kFineBands));
    fast_edges_ = {bin_of(fast, BandPower::kLowEdgeHz), bin_of(fast, 1000), bin_of(fast, 4000),
                   fast.bins};
    reset();
}

void PartFeatures::reset() noexcept {
    values_.fill(0.0f);
    has_recent_ = false;
}

// The logarithms a chunk at a time into a small array, a loop the compiler vectorises, then
// summed in order in double precision: the same sum, bit for bit, as one scalar loop.
TACTUS_VECTOR_CLONES double log_flatness(const float* powers, int count) noexcept {
    constexpr int kChunk = 64;
    float logs[kChunk];
    double log_sum = 0;
    for (int start = 0; start < count; start += kChunk) {
        const int n = std::min(kChunk, count - start);
        for (int k = 0; k < n; ++k) logs[k] = fast_log(powers[start + k] + kTinyPower);
        log_sum = sum_in_order(log_sum, logs, static_cast<size_t>(n));
    }
    const int n = std::max(1, count);
    const double mean = sum_of(powers, std::max(0, count)) / n + kTinyPower;
    return log_sum / n - std::log(mean);
}

bool PartFeatures::compute(const Added& a) noexcept {
    const auto sum = [](std::span<const float> x, int from, int to) {
        return sum_of(x.data() + from, std::max(0, to - from));
    };
    const double fine_total = sum(a.fine, fine_edges_[0], fine_edges_[kFineBands]) + a.high;
    const double fast_total = a.low + sum(a.fast, fast_edges_[0], fast_edges_[3]) + a.high;
    if (fine_total <= 0 || fast_total <= 0) return false;
    size_t v = 0;
    for (int b = 0; b < kFineBands; ++b)
        values_[v++] = static_cast<float>(
            log_share(sum(a.fine, fine_edges_[b], fine_edges_[b + 1]), fine_total));
    values_[v++] = static_cast<float>(log_share(a.low, fast_total));
    values_[v++] = static_cast<float>(log_share(a.high, fast_total));
    values_[v++] =
        static_cast<float>(log_share(sum(a.fast, fast_edges_[0], fast_edges_[1]), fast_total));
    values_[v++] =
        static_cast<float>(log_share(sum(a.fast, fast_edges_[1], fast_edges_[2]), fast_total));
    values_[v++] =
        static_cast<float>(log_share(sum(a.fast, fast_edges_[2], fast_edges_[3]), fast_total));
    // Flatness from the third band's edge up (164 Hz at the defaults).
    const int first = fine_edges_[2], last = fine_edges_[kFineBands];
    values_[v++] = static_cast<float>(log_flatness(a.fine.data() + first, last - first));
    const double bed = sum(a.fine_bed, fine_edges_[0], fine_edges_[kFineBands]);
    values_[v++] = static_cast<float>(std::clamp(
        std::log10((fine_total + kTinyPower) / (bed + kTinyPower)), -kRiseLimit, kRiseLimit));
    values_[v++] = static_cast<float>(a.decay_db / 10);
    // The first hit of a song is its own recent mean.
    if (!has_recent_) std::copy_n(values_.begin(), kOwn, recent_.begin());
    has_recent_ = true;
    for (size_t i = 0; i < kOwn; ++i) {
        values_[kOwn + i] = values_[i] - recent_[i];
        recent_[i] += values_[kOwn + i] / static_cast<float>(kRecentHits);
    }
    return true;
}

}  // namespace tactus
