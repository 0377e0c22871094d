// AHAP (Apple Core Haptics): haptic_formats.hpp.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tactus/export/haptic_formats.hpp"
#include "tactus/export/json_numbers.hpp"

namespace tactus {
namespace {

using Json = nlohmann::ordered_json;
using namespace json_numbers;

// The breakpoints within [begin, end], with the envelope's values at both ends.
std::vector<Breakpoint> window(const std::vector<Breakpoint>& points, double begin, double end) {
    const auto value_at = [&](double t) {
        const auto after =
            std::lower_bound(points.begin(), points.end(), t,
                             [](const Breakpoint& p, double x) { return p.time_s < x; });
        if (after == points.begin()) return points.front().value;
        if (after == points.end()) return points.back().value;
        const auto before = after - 1;
        if (after->time_s <= before->time_s) return after->value;
        return before->value + (after->value - before->value) * (t - before->time_s) /
                                   (after->time_s - before->time_s);
    };
    std::vector<Breakpoint> out{{begin, value_at(begin)}};
    for (const Breakpoint& p : points)
        if (p.time_s > begin && p.time_s < end) out.push_back(p);
    out.push_back({end, value_at(end)});
    return out;
}

// ParameterCurves of at most kAhapMaxCurvePoints points; each starts where the last ended.
void add_curves(Json& pattern, const char* parameter, const std::vector<Breakpoint>& points) {
    for (size_t first = 0; first + 1 < points.size(); first += kAhapMaxCurvePoints - 1) {
        const size_t last = std::min(points.size() - 1, first + kAhapMaxCurvePoints - 1);
        Json controls = Json::array();
        for (size_t i = first; i <= last; ++i)
            controls.push_back({{"Time", time_value(points[i].time_s - points[first].time_s)},
                                {"ParameterValue", level(points[i].value)}});
        pattern.push_back({{"ParameterCurve",
                            {{"ParameterID", parameter},
                             {"Time", time_value(points[first].time_s)},
                             {"ParameterCurveControlPoints", controls}}}});
    }
}

}  // namespace

std::string ahap_text(const HapticTrack& track) {
    Json pattern = Json::array();
    for (const HapticOnset& onset : track.onsets)
        pattern.push_back(
            {{"Event",
              {{"Time", time_value(onset.time_s)},
               {"EventType", "HapticTransient"},
               {"EventParameters",
                {{{"ParameterID", "HapticIntensity"}, {"ParameterValue", level(onset.intensity)}},
                 {{"ParameterID", "HapticSharpness"},
                  {"ParameterValue", level(onset.sharpness)}}}}}}});
    const auto intensity = simplify(track.intensity, HapticTrack::kStepS, kIntensityTolerance);
    const auto sharpness = simplify(track.sharpness, HapticTrack::kStepS, kSharpnessTolerance);
    const double duration_s = track.duration_s();
    for (double begin = 0; begin < duration_s; begin += kAhapMaxEventS) {
        const double end = std::min(duration_s, begin + kAhapMaxEventS);
        // The event plays at full intensity and zero sharpness; the curves set both (intensity
        // control multiplies, sharpness control adds).
        pattern.push_back({{"Event",
                            {{"Time", time_value(begin)},
                             {"EventType", "HapticContinuous"},
                             {"EventDuration", time_value(end - begin)},
                             {"EventParameters",
                              {{{"ParameterID", "HapticIntensity"}, {"ParameterValue", 1.0}},
                               {{"ParameterID", "HapticSharpness"}, {"ParameterValue", 0.0}}}}}}});
        add_curves(pattern, "HapticIntensityControl", window(intensity, begin, end));
        add_curves(pattern, "HapticSharpnessControl", window(sharpness, begin, end));
    }
    // An event has no field of its own for what the hit was: each onset's drum part and strength
    // go in the Metadata (which Core Haptics does not read), at its transient's time.
    Json parts = Json::array();
    for (const HapticOnset& onset : track.onsets)
        parts.push_back({{"Time", time_value(onset.time_s)},
                         {"Part", name_of(onset.part)},
                         {"StrengthDB", decibels(onset.strength_db)}});
    const Json ahap = {{"Version", 1.0},
                       {"Metadata",
                        {{"Project", track.info.source},
                         {"Created", "tactus " + track.info.version},
                         {"Description", track.description()},
                         {"Onsets", parts}}},
                       {"Pattern", pattern}};
    return ahap.dump(1) + "\n";
}

}  // namespace tactus
