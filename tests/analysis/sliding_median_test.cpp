// The sliding median (analysis/sliding_median.hpp) is the selection it replaces: the element at
// the middle of the last N values sorted, for streams with ties and for every N from 1.
#include "tactus/analysis/sliding_median.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <random>
#include <vector>

namespace tactus {
namespace {

double selected(const std::deque<double>& last) {
    std::vector<double> copy(last.begin(), last.end());
    const auto middle = copy.begin() + static_cast<std::ptrdiff_t>(copy.size() / 2);
    std::nth_element(copy.begin(), middle, copy.end());
    return *middle;
}

TEST(SlidingMedian, EqualsTheSelectionOverTheLastValues) {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> small(0, 5);  // many ties
    std::normal_distribution<double> wide(0.0, 10.0);
    for (int length : {1, 2, 3, 8, 41, 42}) {
        SlidingMedian median;
        median.prepare(length);
        median.fill(0.5);
        std::deque<double> last(static_cast<size_t>(length), 0.5);
        for (int i = 0; i < 2000; ++i) {
            ASSERT_EQ(median.median(), selected(last)) << "length " << length << ", value " << i;
            const double value = i % 3 == 0 ? wide(random) : small(random);
            median.push(value);
            last.pop_front();
            last.push_back(value);
        }
    }
}

TEST(SlidingMedian, FillForgetsThePast) {
    SlidingMedian median;
    median.prepare(5);
    for (double v : {9.0, 8.0, 7.0, 6.0, 5.0}) median.push(v);
    EXPECT_EQ(median.median(), 7.0);
    median.fill(0.0);
    EXPECT_EQ(median.median(), 0.0);
    median.push(4.0);
    median.push(3.0);
    EXPECT_EQ(median.median(), 0.0);
    median.push(2.0);
    EXPECT_EQ(median.median(), 2.0);
}

}  // namespace
}  // namespace tactus
