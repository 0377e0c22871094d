// sum_in_order adds its terms in the order a scalar loop does, bit for bit, at every length (the
// part model's scores and the spectral flatness rely on it: analysis/model_terms.hpp,
// analysis/part_features.cpp), on terms whose sum depends on the order; and linear_score, which
// reads its products through it, scores as the plain loop does; sum_of_squares, whose partial
// sums the onset refinement reads, is the squares' sum within rounding, every term counted once.
#include "tactus/core/fast_math.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "tactus/analysis/model_terms.hpp"

namespace tactus {
namespace {

// Terms from 1e-8 to 1e8 of either sign: rounding makes their sum depend on the order.
template <typename T>
std::vector<T> wild_terms(size_t count, uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> exponent(-8, 8), sign(-1, 1);
    std::vector<T> terms(count);
    for (T& t : terms)
        t = static_cast<T>((sign(random) < 0 ? -1 : 1) * std::pow(10, exponent(random)));
    return terms;
}

template <typename T>
double scalar_sum(double sum, const std::vector<T>& terms) {
    for (const T t : terms) sum += t;
    return sum;
}

uint64_t bits(double x) {
    return std::bit_cast<uint64_t>(x);
}

TEST(SumInOrder, IsTheScalarLoopsSumBitForBit) {
    int order_mattered = 0;
    for (size_t count = 0; count <= 70; ++count) {
        const auto doubles = wild_terms<double>(count, static_cast<uint32_t>(count));
        const auto floats = wild_terms<float>(count, static_cast<uint32_t>(count + 100));
        EXPECT_EQ(bits(sum_in_order(0.5, doubles.data(), count)), bits(scalar_sum(0.5, doubles)))
            << count;
        EXPECT_EQ(bits(sum_in_order(-3.0, floats.data(), count)), bits(scalar_sum(-3.0, floats)))
            << count;
        order_mattered += bits(sum_of(floats.data(), static_cast<int>(count)) - 3.0) !=
                          bits(scalar_sum(-3.0, floats));
    }
    EXPECT_GT(order_mattered, 30);  // the terms do tell orders apart
}

TEST(SumOfSquares, IsTheSquaresSumAtEveryLength) {
    for (int count = 0; count <= 70; ++count) {
        std::vector<float> x(static_cast<size_t>(count));
        for (int i = 0; i < count; ++i) x[static_cast<size_t>(i)] = static_cast<float>(i + 1);
        // 1 + 4 + ... + n^2, exact in double: any term missed or counted twice shows
        const double exact = count * (count + 1.0) * (2.0 * count + 1.0) / 6.0;
        EXPECT_EQ(sum_of_squares(x.data(), count), exact) << count;
        const auto wild =
            wild_terms<float>(static_cast<size_t>(count), static_cast<uint32_t>(count));
        double plain = 0.0;
        for (const float v : wild) plain += static_cast<double>(v) * v;
        EXPECT_NEAR(sum_of_squares(wild.data(), count), plain, 1e-14 * plain) << count;
    }
}

TEST(LinearScore, ScoresAsThePlainLoop) {
    for (size_t count : {1, 7, 64, 150, 200}) {
        const auto z = wild_terms<float>(count, 7), weights = wild_terms<float>(count, 8);
        double expected = 0.25;
        for (size_t k = 0; k < count; ++k) expected += weights[k] * z[k];
        EXPECT_EQ(bits(linear_score(z, weights.data(), 0.25)), bits(expected)) << count;
    }
}

}  // namespace
}  // namespace tactus
