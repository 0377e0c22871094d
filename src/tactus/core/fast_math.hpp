// Arithmetic kernels for the analysis hot loops, written so that the compiler can vectorise
// them for any x86-64 (SSE2) without -ffast-math: sums in independent double partial sums
// (partial_sums: a fixed, block-size-independent order, so results are reproducible), a sum in a
// scalar loop's own order with less of the loop's overhead (sum_in_order), and a natural logarithm
// from the float's exponent and a short series (Abramowitz & Stegun 4.1.27): ln x = e ln 2 + 2
// atanh(s), s = (m - 1) / (m + 1), m in [sqrt(1/2), sqrt(2)), to within 2 float ulps, where
// std::log costs a library call per value.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace tactus {

// ln x for normal, finite x > 0.
inline float fast_log(float x) noexcept {
    constexpr uint32_t kSqrtHalfBits = 0x3f3504f3;  // sqrt(1/2) as a float
    const auto bits = std::bit_cast<uint32_t>(x);
    const int32_t exponent = static_cast<int32_t>(bits - kSqrtHalfBits) >> 23;
    const float m = std::bit_cast<float>(bits - (static_cast<uint32_t>(exponent) << 23));
    const float s = (m - 1.0f) / (m + 1.0f), z = s * s;
    const float series = 1.0f + z * (1.0f / 3 + z * (1.0f / 5 + z * (1.0f / 7 + z * (1.0f / 9))));
    constexpr float kLn2 = 0.693147180559945309f;
    return static_cast<float>(exponent) * kLn2 + 2.0f * s * series;
}

// sum term(i) for i < n in kLanes independent partial sums: lane j takes i = j (mod kLanes), the
// tail lane 0, and the lanes are added pairwise at the end: (s0 + s1) + (s2 + s3) for four.
// Always inlined, so each caller's vector clone (TACTUS_VECTOR_CLONES) vectorises it.
template <int kLanes, typename Term>
[[gnu::always_inline]] inline double partial_sums(int n, Term term) noexcept {
    static_assert(kLanes == 4 || kLanes == 8);
    double s[kLanes] = {};
    int i = 0;
    for (; i + kLanes <= n; i += kLanes)
        for (int j = 0; j < kLanes; ++j) s[j] += term(i + j);
    for (; i < n; ++i) s[0] += term(i);
    if constexpr (kLanes == 4)
        return (s[0] + s[1]) + (s[2] + s[3]);
    else
        return ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
}

// sum x[i] for i < n.
inline double sum_of(const float* x, int n) noexcept {
    return partial_sums<4>(n, [x](int i) { return static_cast<double>(x[i]); });
}

// sum x[i]^2 for i < n, in double: eight lanes, two AVX vectors (four SSE2 ones).
inline double sum_of_squares(const float* x, int n) noexcept {
    return partial_sums<8>(n, [x](int i) { return static_cast<double>(x[i]) * x[i]; });
}

// sum + x[0] + x[1] + ... + x[n - 1], added in that order (the same, bit for bit, as one scalar
// loop), four terms a step: a quarter of the loop's own instructions.
template <typename T>
double sum_in_order(double sum, const T* x, size_t n) noexcept {
    size_t i = 0;
    for (; i + 4 <= n; i += 4) sum = sum + x[i] + x[i + 1] + x[i + 2] + x[i + 3];
    for (; i < n; ++i) sum += x[i];
    return sum;
}

// sum w[i] x[i] for i < n.
inline double dot(const double* w, const float* x, int n) noexcept {
    return partial_sums<4>(n, [w, x](int i) { return w[i] * x[i]; });
}

}  // namespace tactus
