// Fewer rows for a plot, its extremes kept: rows (time, then one value per series) are cut into
// buckets of consecutive rows, and of each bucket only the rows holding a series' minimum or
// maximum are kept, as they are, in time order. Every series keeps its peak and its dips at their
// own times (taking every k-th row drops the peaks: a 5.4-minute song's felt envelope, peak 1.0,
// was drawn topping out at 0.48), and every row kept is a real one. NaN (a gap) is never an
// extreme. Offline.
#pragma once

#include <cstddef>
#include <vector>

namespace tactus {

// At most about `max_rows` rows (buckets: max_rows / (2 x series)); all of them if fewer.
std::vector<std::vector<double>> thin_rows(const std::vector<std::vector<double>>& rows,
                                           size_t max_rows);

}  // namespace tactus
