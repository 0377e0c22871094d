// How the fitted models of analysis/part_model.hpp read their numbers, as eval/fit_parts.py fits
// them (quadratic(), fit()): the numbers, then their pairwise products x_i x_j for i <= j; each
// term standardised by the fit's mean and scale; a class's score the bias plus the weighed terms.
// Any thread: never allocates.
#pragma once

#include <cstddef>
#include <span>

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

inline double linear_score(std::span<const float> z, const float* weights, double bias) noexcept {
    double score = bias;
    for (size_t k = 0; k < z.size(); ++k) score += weights[k] * z[k];
    return score;
}

}  // namespace tactus
