#include "tactus/export/thin_rows.hpp"

#include <algorithm>
#include <cmath>

namespace tactus {

std::vector<std::vector<double>> thin_rows(const std::vector<std::vector<double>>& rows,
                                           size_t max_rows) {
    if (rows.size() <= max_rows) return rows;
    const size_t series = rows.front().size() > 1 ? rows.front().size() - 1 : 1;
    const size_t buckets = std::max<size_t>(1, max_rows / (2 * series));
    const size_t size = (rows.size() + buckets - 1) / buckets;
    std::vector<std::vector<double>> out;
    std::vector<size_t> kept;
    for (size_t first = 0; first < rows.size(); first += size) {
        const size_t end = std::min(rows.size(), first + size);
        kept.clear();
        for (size_t c = 1; c < rows[first].size(); ++c) {
            size_t low = end, high = end;
            for (size_t i = first; i < end; ++i) {
                const double v = rows[i][c];
                if (std::isnan(v)) continue;
                if (low == end || v < rows[low][c]) low = i;
                if (high == end || v > rows[high][c]) high = i;
            }
            if (low != end) kept.insert(kept.end(), {low, high});
        }
        std::sort(kept.begin(), kept.end());
        kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
        for (const size_t i : kept) out.push_back(rows[i]);
    }
    return out;
}

}  // namespace tactus
