#include "tactus/analysis/onset_rises.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/analysis/band_power.hpp"
#include "tactus/analysis/model_terms.hpp"
#include "tactus/analysis/part_model.hpp"
#include "tactus/core/fast_math.hpp"
#include "tactus/core/vector_clones.hpp"

namespace tactus {
namespace {
// Powers below -100 dB re a full-scale sine's count as that: a band rising from digital silence
// reads a large rise, not an infinite one.
constexpr double kFloorPower = 1e-10;
constexpr double kRiseLimit = 6;  // log10 of a power's rise

float rise(double before, double added) {
    return static_cast<float>(
        std::min(kRiseLimit, std::log10((before + added + kFloorPower) / (before + kFloorPower))));
}

// The flatness of what the onset added from `first` up.
float flatness(std::span<const float> powers, int first) {
    return static_cast<float>(
        log_flatness(powers.data() + first, static_cast<int>(powers.size()) - first));
}
}  // namespace

void OnsetRises::prepare(SpectrumShape fast, SpectrumShape fine) {
    const auto bin_of = [](SpectrumShape s, double hz) {
        return std::clamp(static_cast<int>(std::ceil(hz / s.bin_hz)), 1, s.bins);
    };
    fast_edges_ = {bin_of(fast, BandPower::kLowEdgeHz), bin_of(fast, 400), bin_of(fast, 1000),
                   bin_of(fast, 2500), fast.bins};
    fine_first_ = bin_of(fine, BandPower::kLowEdgeHz);
    values_.fill(0.0f);
}

void OnsetRises::compute(const Frame& frame) noexcept {
    size_t v = 0;
    values_[v++] = rise(frame.low.before, frame.low.added);
    for (size_t b = 0; b + 1 < fast_edges_.size(); ++b) {
        const int first = fast_edges_[b], count = fast_edges_[b + 1] - first;
        values_[v++] = rise(sum_of(frame.fast_before.data() + first, count),
                            sum_of(frame.fast_added.data() + first, count));
    }
    values_[v++] = rise(frame.high.before, frame.high.added);
    values_[v++] = rise(frame.loudness.before, frame.loudness.added);
    values_[v++] = flatness(frame.fast_added, fast_edges_[0]);
    values_[v++] = flatness(frame.fine_added, fine_first_);
    values_[v++] = frame.high_over_recent;
}

// The logistic of the model's score on the values and their pairwise products (model_terms.hpp).
TACTUS_VECTOR_CLONES double OnsetRises::drum_probability() const noexcept {
    using namespace part_model;
    std::array<float, kDrumTerms> z{};
    put_quadratic(values_, z.data());
    standardise(z, kDrumMean.data(), kDrumScale.data());
    return 1 / (1 + std::exp(-linear_score(z, kDrumWeights.data(), kDrumBias)));
}

}  // namespace tactus
