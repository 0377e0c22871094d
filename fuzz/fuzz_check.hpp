// What every fuzz target asserts besides "no crash": errors are one line, settings stay in the
// parameter table's ranges. A violated check aborts, which libFuzzer reports as a finding.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "tactus/params/params.hpp"

namespace tactus::fuzz {

inline void check_message(const char* message) {
    if (std::strlen(message) > 0 && std::strchr(message, '\n') == nullptr) return;
    std::fprintf(stderr, "error message is not one line: [%s]\n", message);
    std::abort();
}

inline void check_in_range(const Settings& settings) {
    for (int i = 0; i < static_cast<int>(P::count); ++i) {
        const ParamSpec& s = spec(static_cast<P>(i));
        const double value = settings[static_cast<P>(i)];
        if (value >= s.min && value <= s.max) continue;
        std::fprintf(stderr, "%s = %g is outside %g to %g\n", s.key.data(), value, s.min, s.max);
        std::abort();
    }
}

// The same bits in every parameter (-0.0 is not 0.0): a round trip loses nothing.
inline bool same_bits(const Settings& a, const Settings& b) {
    for (int i = 0; i < static_cast<int>(P::count); ++i) {
        const double x = a[static_cast<P>(i)], y = b[static_cast<P>(i)];
        // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison): the bits are what is compared
        if (std::memcmp(&x, &y, sizeof x) != 0) return false;
    }
    return true;
}

}  // namespace tactus::fuzz
