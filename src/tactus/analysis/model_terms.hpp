// How the fitted models of analysis/part_model.hpp read their numbers, as eval/fit_parts.py fits
// them (quadratic(), fit()): the numbers, then their pairwise products x_i x_j for i <= j; each
// term standardised by the fit's mean and scale; a class's score the bias plus the weighed terms.
// Any thread: never allocates.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>

#include "tactus/core/fast_math.hpp"

namespace tactus {

// Writes x, then x_i x_j for i <= j, from `out` on; returns the position after them.
inline float* put_quadratic(std::span<const float> x, float* out) noexcept {
    for (const float v : x) *out++ = v;
    for (size_t i = 0; i < x.size(); ++i)
        for (size_t j = i; j < x.size(); ++j) *out++ = x[i] * x[j];
    return out;
}

// (z - mean) / scale, term by term.
inline void standardise(std::span<float> z, const float* mean, const float* scale) noexcept {
    for (size_t k = 0; k < z.size(); ++k) z[k] = (z[k] - mean[k]) / scale[k];
}

// bias + the sum of weights[k] z[k]: each product rounded in float, as the fit's reader has
// always read them, then summed in order in double. The products a chunk at a time into a small
// array (a loop the compiler vectorises), then the sum: the same, bit for bit, as one scalar loop.
inline double linear_score(std::span<const float> z, const float* weights, double bias) noexcept {
    constexpr size_t kChunk = 64;
    std::array<double, kChunk> products;
    double score = bias;
    for (size_t start = 0; start < z.size(); start += kChunk) {
        const size_t count = std::min(kChunk, z.size() - start);
        for (size_t k = 0; k < count; ++k) products[k] = weights[start + k] * z[start + k];
        score = sum_in_order(score, products.data(), count);
    }
    return score;
}

}  // namespace tactus
