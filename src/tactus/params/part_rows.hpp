// The three rows of one drum part (parts.<name>.gain_db, brightness_hz, decay_ms: the shape its
// pulse takes once its part is decided, mapping/mapper.hpp), generated at compile time from its
// name and how the help texts call it, so the four parts are written once (params.cpp).
#pragma once

#include <array>
#include <cstdint>

#include "tactus/params/mapping_rows.hpp"

namespace tactus::params_detail {

constexpr double kPartGainSmoothingMs = 20;

// `gain`: the part's first row (the enum lists the three in this order), `id` its stable id; the
// other two follow it.
template <Text name, Text noun>
constexpr std::array<ParamSpec, 3> part_rows(P gain, uint32_t id) {
    using enum ParamType;
    using enum ParamChange;
    using enum ParamCurve;
    const auto row = [&](int k) { return static_cast<P>(static_cast<int>(gain) + k); };
    return {{
        {row(0), id, JoinedText<"parts.", name, ".gain_db">::view, "dB", real, -60, 12, 0, lin,
         live, kPartGainSmoothingMs,
         JoinedText<"gain of ", noun, "'s pulse once its part is decided (-60 = off)">::view},
        {row(1), id + 1, JoinedText<"parts.", name, ".brightness_hz">::view, "Hz", real, 0, 8000, 0,
         lin, live, 0,
         JoinedText<"brightness ", noun,
                    "'s pulse is mapped from once its part is decided, through the frequency "
                    "mapping (0 = its own)">::view},
        {row(2), id + 2, JoinedText<"parts.", name, ".decay_ms">::view, "ms", real, 0, 5000, 0, lin,
         live, 0,
         JoinedText<"decay of ", noun,
                    "'s pulse once its part is decided (0 = envelope.decay_ms)">::view},
    }};
}

}  // namespace tactus::params_detail
