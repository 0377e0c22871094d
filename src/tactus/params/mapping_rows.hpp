// The seven rows of one mapping group (mapping.<name>.source, in_min, in_max, out_min, out_max,
// curve, smoothing_ms), generated at compile time from one description, so the six groups of the
// parameter table are written once (params.cpp). Their keys and help texts are joined at compile
// time (JoinedText) and live as long as the table.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string_view>

#include "tactus/params/params.hpp"

namespace tactus::params_detail {

// A string literal as a template argument.
template <size_t N>
struct Text {
    char chars[N]{};
    constexpr Text(const char (&text)[N]) { std::copy_n(text, N, chars); }  // NOLINT: implicit
};

// The parts joined into one string with static storage.
template <Text... parts>
struct JoinedText {
    static constexpr size_t kLength = ((sizeof(parts.chars) - 1) + ...);
    static constexpr std::array<char, kLength + 1> kChars = [] {
        std::array<char, kLength + 1> out{};
        size_t at = 0;
        ((std::copy_n(parts.chars, sizeof(parts.chars) - 1, out.begin() + at),
          at += sizeof(parts.chars) - 1),
         ...);
        return out;
    }();
    static constexpr std::string_view view{kChars.data(), kLength};
};

// What differs between mapping groups, besides their names (mapping_rows' arguments).
struct MappingGroup {
    P source;            // the group's first row: the enum lists the seven in this order
    uint32_t source_id;  // its stable id; the other six follow it
    double source_default;
    std::string_view source_help;
    double in_min, in_max;  // defaults (the inputs take any value: -1e6 to 1e6)
    std::string_view out_unit;
    double out_low, out_high;  // the outputs' range
    ParamCurve out_curve;
    double out_min, out_max;  // defaults
    double curve;             // default: lin, log or exp (kCurveNames)
    double smoothing_max_ms, smoothing_ms;
};

constexpr std::span<const std::string_view> kSourceChoices{kFeatureSourceNames};
constexpr std::span<const std::string_view> kCurveChoices{kCurveNames};
constexpr double kInputLimit = 1e6;
constexpr double kLevelSmoothingMs = 20;  // how in/out changes glide

// mapping.<name>.*: "<quantity> at in_min<note>", "one-pole time constant applied to the mapped
// <smoothed>".
template <Text name, Text quantity, Text note, Text smoothed>
constexpr std::array<ParamSpec, 7> mapping_rows(const MappingGroup& g) {
    using enum ParamType;
    using enum ParamChange;
    using enum ParamCurve;
    const auto row = [&](int k) { return static_cast<P>(static_cast<int>(g.source) + k); };
    constexpr double kLastSource = kFeatureSourceNames.size() - 1;
    constexpr double kLastCurve = kCurveNames.size() - 1;
    return {{
        {row(0), g.source_id, JoinedText<"mapping.", name, ".source">::view, "", choice, 0,
         kLastSource, g.source_default, lin, live, 0, g.source_help, kSourceChoices},
        {row(1), g.source_id + 1, JoinedText<"mapping.", name, ".in_min">::view, "", real,
         -kInputLimit, kInputLimit, g.in_min, lin, live, kLevelSmoothingMs,
         "source value mapped to out_min"},
        {row(2), g.source_id + 2, JoinedText<"mapping.", name, ".in_max">::view, "", real,
         -kInputLimit, kInputLimit, g.in_max, lin, live, kLevelSmoothingMs,
         "source value mapped to out_max"},
        {row(3), g.source_id + 3, JoinedText<"mapping.", name, ".out_min">::view, g.out_unit, real,
         g.out_low, g.out_high, g.out_min, g.out_curve, live, kLevelSmoothingMs,
         JoinedText<quantity, " at in_min", note>::view},
        {row(4), g.source_id + 4, JoinedText<"mapping.", name, ".out_max">::view, g.out_unit, real,
         g.out_low, g.out_high, g.out_max, g.out_curve, live, kLevelSmoothingMs,
         JoinedText<quantity, " at in_max", note>::view},
        {row(5), g.source_id + 5, JoinedText<"mapping.", name, ".curve">::view, "", choice, 0,
         kLastCurve, g.curve, lin, live, 0, "lin, log (ratio to ratio) or exp (dB to amplitude)",
         kCurveChoices},
        {row(6), g.source_id + 6, JoinedText<"mapping.", name, ".smoothing_ms">::view, "ms", real,
         0, g.smoothing_max_ms, g.smoothing_ms, lin, live, 0,
         JoinedText<"one-pole time constant applied to the mapped ", smoothed>::view},
    }};
}

// The table's parts joined, in order.
template <size_t... N>
constexpr std::array<ParamSpec, (N + ...)> joined_rows(const std::array<ParamSpec, N>&... parts) {
    std::array<ParamSpec, (N + ...)> out{};
    size_t at = 0;
    ((std::copy(parts.begin(), parts.end(), out.begin() + at), at += N), ...);
    return out;
}

}  // namespace tactus::params_detail
