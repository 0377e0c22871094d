// .haptic (Meta Haptics SDK / Lofelt v1) and Android waveforms: haptic_formats.hpp.
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
          {"description", track.info.describe()}}},
        {"signals",
         {{"continuous", {{"envelopes", {{"amplitude", amplitude}, {"frequency", frequency}}}}}}}};
    return haptic.dump(1) + "\n";
}

std::string android_waveform_text(const HapticTrack& track) {
    // Steps that each hold one amplitude while the envelope stays within kAndroidStepRange.
    Json timings = Json::array(), amplitudes = Json::array();
    const auto& v = track.intensity;
    const auto ms_per_step = HapticTrack::kStepS * 1e3;
    int64_t total_ms = 0;
    for (size_t first = 0; first < v.size();) {
        double low = v[first], high = v[first];
        size_t end = first + 1;
        for (; end < v.size(); ++end) {
            const double l = std::min(low, v[end]), h = std::max(high, v[end]);
            if (h - l > kAndroidStepRange) break;
            low = l;
            high = h;
        }
        const int amplitude =
            static_cast<int>(std::lround(0.5 * (low + high) * kAndroidMaxAmplitude));
        const auto ms =
            static_cast<int64_t>(std::lround(static_cast<double>(end - first) * ms_per_step));
        if (!amplitudes.empty() && amplitudes.back().get<int>() == amplitude) {
            timings.back() = timings.back().get<int64_t>() + ms;
        } else {
            timings.push_back(ms);
            amplitudes.push_back(amplitude);
        }
        total_ms += ms;
        first = end;
    }
    Json onsets = Json::array(), parts = Json::array(), strengths = Json::array();
    for (const HapticOnset& onset : track.onsets) {
        onsets.push_back(time_value(onset.time_s * 1e3));
        parts.push_back(name_of(onset.part));
        strengths.push_back(decibels(onset.strength_db));
    }
    const Json waveform = {
        {"api_level", kAndroidWaveformApiLevel},
        {"call", "VibrationEffect.createWaveform(timings, amplitudes, repeat)"},
        {"requires",
         "Vibrator.hasAmplitudeControl() (else amplitudes other than 0 play at the default)"},
        {"repeat", -1},
        {"duration_ms", total_ms},
        {"timings", timings},
        {"amplitudes", amplitudes},
        {"onsets_ms", onsets},
        {"onset_parts", parts},
        {"onset_strengths_db", strengths},
        {"metadata", {{"description", track.info.describe()}}}};
    return waveform.dump(1) + "\n";
}

std::string haptic_format_of(const std::string& path) {
    const auto ends_with = [&](std::string_view end) {
        if (path.size() < end.size()) return false;
        std::string tail = path.substr(path.size() - end.size());
        std::transform(tail.begin(), tail.end(), tail.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        return tail == end;
    };
    for (const char* format : {".ahap", ".haptic", ".android.json", ".ogg"})
        if (ends_with(format)) return format;
    return {};
}

}  // namespace tactus
