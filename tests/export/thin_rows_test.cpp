// Thinning a plot's rows keeps every series' extremes: one spike among a million rows survives
// at its own time, each series' minimum and maximum survive in a plot of several, every row kept
// is one of the input's in time order, gaps (NaN) are never chosen, and the count stays near
// the bound.
#include "tactus/export/thin_rows.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tactus {
namespace {

TEST(ThinRows, OneSpikeAmongAMillionRowsSurvives) {
    std::vector<std::vector<double>> rows;
    for (int i = 0; i < 1'000'000; ++i) rows.push_back({i * 1e-3, 0.01 * std::sin(i * 0.1)});
    rows[654'321][1] = 1.0;
    const auto thin = thin_rows(rows, 4000);
    EXPECT_LE(thin.size(), 4000u);
    EXPECT_GE(thin.size(), 3000u);
    const auto peak = std::max_element(thin.begin(), thin.end(),
                                       [](const auto& a, const auto& b) { return a[1] < b[1]; });
    EXPECT_EQ((*peak)[1], 1.0);
    EXPECT_DOUBLE_EQ((*peak)[0], 654.321);  // at its own time
    EXPECT_TRUE(std::is_sorted(thin.begin(), thin.end()));
}

TEST(ThinRows, EverySeriesKeepsItsMinimumAndMaximum) {
    std::vector<std::vector<double>> rows;
    for (int i = 0; i < 100'000; ++i) rows.push_back({i * 1e-3, 0.0, 5.0, NAN});
    rows[10][1] = -3;
    rows[99'990][1] = 7;
    rows[50'000][2] = 9;
    rows[50'001][2] = -9;
    const auto thin = thin_rows(rows, 600);
    EXPECT_LE(thin.size(), 600u);
    const auto column = [&](size_t c, auto pick) {
        double best = thin.front()[c];
        for (const auto& r : thin) best = pick(best, r[c]);
        return best;
    };
    const auto min = [](double a, double b) { return std::min(a, b); };
    const auto max = [](double a, double b) { return std::max(a, b); };
    EXPECT_EQ(column(1, min), -3);
    EXPECT_EQ(column(1, max), 7);
    EXPECT_EQ(column(2, min), -9);
    EXPECT_EQ(column(2, max), 9);
    for (const auto& r : thin) {  // rows as they were
        const auto& original = rows[static_cast<size_t>(std::lround(r[0] * 1e3))];
        EXPECT_EQ(r[1], original[1]);
        EXPECT_EQ(r[2], original[2]);
        EXPECT_TRUE(std::isnan(r[3]));
    }
}

TEST(ThinRows, FewRowsAreKeptAsTheyAre) {
    const std::vector<std::vector<double>> rows = {{0, 1}, {1, NAN}, {2, 3}};
    EXPECT_EQ(thin_rows(rows, 4000).size(), 3u);
}

}  // namespace
}  // namespace tactus
