// Android envelope effects (VibrationEffect.BasicEnvelopeBuilder): haptic_formats.hpp.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tactus/export/haptic_formats.hpp"
#include "tactus/export/json_numbers.hpp"

namespace tactus {
namespace {

using Json = nlohmann::ordered_json;
using namespace json_numbers;

struct ControlPoint {
    double intensity = 0, sharpness = 0;
    int64_t duration_ms = 0;  // from the point before (the effect's start for the first)
};

// The felt envelope's breakpoints within kIntensityTolerance, each at least kAndroidMinStepMs
// after the control point before (the builder's shortest ramp on a phone). Of the breakpoints
// closer than that to the last point, the highest is kept, moved to kAndroidMinStepMs after it:
// a hit's peak, a few ms after its start, comes up to 20 ms late rather than not at all. Each
// with the sharpness at its time; the last at zero intensity, as the builder requires.
std::vector<ControlPoint> control_points(const HapticTrack& track) {
    std::vector<ControlPoint> points;
    const auto sharpness_at = [&](double time_s) {
        const auto step = static_cast<size_t>(std::lround(time_s / HapticTrack::kStepS));
        return track.sharpness[std::min(step, track.sharpness.size() - 1)];
    };
    int64_t at_ms = 0;     // the last point's time; the builder starts at zero intensity at 0
    Breakpoint held{};     // the highest breakpoint too close to the last point,
    bool holding = false;  // when there is one
    const auto place = [&](Breakpoint b, int64_t ms) {
        points.push_back({b.value, sharpness_at(b.time_s), ms - at_ms});
        at_ms = ms;
        holding = false;
    };
    for (const Breakpoint& b :
         simplify(track.intensity, HapticTrack::kStepS, kIntensityTolerance)) {
        const int64_t ms = std::lround(b.time_s * 1e3);
        if (holding && ms >= at_ms + kAndroidMinStepMs) place(held, at_ms + kAndroidMinStepMs);
        if (ms >= at_ms + kAndroidMinStepMs) {
            place(b, ms);
        } else if (!holding || b.value > held.value) {
            held = b;
            holding = true;
        }
    }
    if (holding) place(held, at_ms + kAndroidMinStepMs);
    if (points.empty() || points.back().intensity > 0)
        points.push_back({0.0, points.empty() ? 0.0 : points.back().sharpness, kAndroidMinStepMs});
    return points;
}

}  // namespace

std::string android_envelope_text(const HapticTrack& track) {
    const std::vector<ControlPoint> points = control_points(track);
    Json controls = Json::array();
    int64_t total_ms = 0;
    for (const ControlPoint& p : points) {
        controls.push_back({{"intensity", level(p.intensity)},
                            {"sharpness", level(p.sharpness)},
                            {"duration_ms", p.duration_ms}});
        total_ms += p.duration_ms;
    }
    Json onsets = Json::array();
    for (const HapticOnset& onset : track.onsets)
        onsets.push_back({{"time_ms", time_value(onset.time_s * 1e3)},
                          {"intensity", level(onset.intensity)},
                          {"sharpness", level(onset.sharpness)},
                          {"part", name_of(onset.part)},
                          {"strength_db", decibels(onset.strength_db)}});
    const Json envelope = {
        {"api_level", kAndroidEnvelopeApiLevel},
        {"builder", "VibrationEffect.BasicEnvelopeBuilder"},
        {"call",
         "new BasicEnvelopeBuilder().setInitialSharpness(initial_sharpness), then "
         "addControlPoint(intensity, sharpness, duration_ms) for each control point, build()"},
        {"requires",
         "Vibrator.areEnvelopeEffectsSupported(); a device takes at most "
         "VibratorEnvelopeEffectInfo.getMaxSize() points, each at least its "
         "getMinControlPointDurationMillis() long: play a longer track in parts"},
        {"duration_ms", total_ms},
        {"min_control_point_ms", kAndroidMinStepMs},
        {"initial_sharpness", level(points.empty() ? 0.0 : points.front().sharpness)},
        {"control_points", controls},
        {"onsets", onsets},
        {"metadata",
         {{"description", track.description()},
          {"felt_full_scale", std::stod(fmt::format("{:.4g}", track.felt_full_scale))}}}};
    return envelope.dump(1) + "\n";
}

}  // namespace tactus
