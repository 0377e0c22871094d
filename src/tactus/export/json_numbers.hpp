// Numbers as the haptic formats' JSON files carry them: times and levels rounded to the steps a
// device resolves, so they print short (0.0676, not 0.06760000000000001).
#pragma once

#include <algorithm>
#include <cmath>

namespace tactus::json_numbers {

// x to `per_unit` steps, divided back by a whole number.
inline double rounded(double x, double per_unit) {
    return std::round(x * per_unit) / per_unit;
}
// Seconds to 0.1 ms.
inline double time_value(double t) {
    return rounded(t, 1e4);
}
// Decibels to 0.01 dB (as `tactus onsets` prints them).
inline double decibels(double db) {
    return rounded(db, 1e2);
}
// A 0 ... 1 level to 0.001.
inline double level(double v) {
    return rounded(std::clamp(v, 0.0, 1.0), 1e3);
}

}  // namespace tactus::json_numbers
