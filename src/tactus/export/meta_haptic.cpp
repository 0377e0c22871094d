// .haptic (Meta Haptics SDK / Lofelt v1): haptic_formats.hpp.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tactus/export/haptic_formats.hpp"
#include "tactus/export/json_numbers.hpp"

namespace tactus {
namespace {

using Json = nlohmann::ordered_json;
using namespace json_numbers;

}  // namespace

std::string meta_haptic_text(const HapticTrack& track) {
    // Amplitude breakpoints, with one at every onset carrying its emphasis.
    std::vector<Breakpoint> points =
        simplify(track.intensity, HapticTrack::kStepS, kIntensityTolerance);
    if (points.size() < 2) points = {{0.0, 0.0}, {std::max(track.duration_s(), 1e-3), 0.0}};
    struct Row {
        double time_s, amplitude;
        const HapticOnset* emphasis;
    };
    std::vector<Row> rows;
    rows.reserve(points.size() + track.onsets.size());
    for (const Breakpoint& p : points)
        rows.push_back({time_value(p.time_s), level(p.value), nullptr});
    for (const HapticOnset& onset : track.onsets) {
        const double t = time_value(std::min(onset.time_s, points.back().time_s));
        const auto at = std::lower_bound(rows.begin(), rows.end(), t,
                                         [](const Row& r, double x) { return r.time_s < x; });
        if (at != rows.end() && at->time_s == t)
            at->emphasis = &onset;
        else
            rows.insert(at, {t, level(track.intensity_at(t)), &onset});
    }
    Json amplitude = Json::array();
    for (const Row& r : rows) {
        Json point = {{"time", r.time_s}, {"amplitude", r.amplitude}};
        if (r.emphasis)
            point["emphasis"] = {{"amplitude", std::max(r.amplitude, level(r.emphasis->intensity))},
                                 {"frequency", level(r.emphasis->sharpness)}};
        amplitude.push_back(point);
    }
    Json frequency = Json::array();
    const double end_s = rows.back().time_s;
    for (const Breakpoint& p : simplify(track.sharpness, HapticTrack::kStepS, kSharpnessTolerance))
        if (time_value(p.time_s) <= end_s)
            frequency.push_back({{"time", time_value(p.time_s)}, {"frequency", level(p.value)}});
    if (frequency.size() < 2)
        frequency = Json::array(
            {{{"time", 0.0}, {"frequency", 0.0}}, {{"time", end_s}, {"frequency", 0.0}}});

    const Json haptic = {
        {"version", {{"major", 1}, {"minor", 0}, {"patch", 0}}},
        {"metadata",
         {{"editor", "tactus " + track.info.version},
          {"source", track.info.source},
          {"project", ""},
          {"tags", Json::array()},
          {"description", track.description()}}},
        {"signals",
         {{"continuous", {{"envelopes", {{"amplitude", amplitude}, {"frequency", frequency}}}}}}}};
    return haptic.dump(1) + "\n";
}

std::string haptic_format_of(const std::string& path) {
    const auto ends_with = [&](std::string_view end) {
        if (path.size() < end.size()) return false;
        std::string tail = path.substr(path.size() - end.size());
        std::transform(tail.begin(), tail.end(), tail.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        return tail == end;
    };
    for (const char* format : {".ahap", ".haptic", ".android.json", ".envelope.json", ".ogg"})
        if (ends_with(format)) return format;
    return {};
}

}  // namespace tactus
