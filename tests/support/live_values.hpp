// For every live parameter, a value other than the one a setting holds, inside the table's range:
// what tests turn while audio runs. Reals move by a quarter of their range (at most 10 units for
// the mapping inputs' +-1e6 ranges, a factor of 2 on log curves); integers, toggles and choices
// go to the next value.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "tactus/params/params.hpp"

namespace tactus::test {

inline double turned_value(const ParamSpec& s, double now) {
    if (s.type != ParamType::real) return now + 1 <= s.max ? now + 1 : s.min;
    double next = 0;
    if (s.curve == ParamCurve::log && now > 0)
        next = now * 2 <= s.max ? now * 2 : now / 2;
    else
        next = now + std::min(10.0, 0.25 * (s.max - s.min));
    if (next > s.max) next = now - std::min(10.0, 0.25 * (s.max - s.min));
    return std::clamp(next, s.min, s.max);
}

// (parameter, turned value) for every live parameter of `settings`.
inline std::vector<std::pair<P, double>> turned_live_values(const Settings& settings) {
    std::vector<std::pair<P, double>> values;
    for (const ParamSpec& s : param_table())
        if (s.change == ParamChange::live)
            values.emplace_back(s.param, turned_value(s, settings[s.param]));
    return values;
}

}  // namespace tactus::test
