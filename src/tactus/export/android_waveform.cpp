// Android waveforms (VibrationEffect.createWaveform): haptic_formats.hpp.
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

struct Step {
    int64_t ms = 0;
    int amplitude = 0;
};

// Steps of at least kAndroidMinStepMs, each holding one amplitude while the envelope stays within
// kAndroidStepRange (longer then); a step is the RMS of the envelope over it (the P channel sums
// energy over time: the same energy is felt alike) and off below `lowest` (1-255).
std::vector<Step> steps_of(const std::vector<double>& v, int lowest) {
    const auto min_steps =
        static_cast<size_t>(std::lround(kAndroidMinStepMs * 1e-3 / HapticTrack::kStepS));
    std::vector<Step> steps;
    for (size_t first = 0; first < v.size();) {
        double low = v[first], high = v[first];
        size_t end = first + 1;
        for (; end < v.size(); ++end) {
            const double l = std::min(low, v[end]), h = std::max(high, v[end]);
            if (h - l > kAndroidStepRange) break;
            low = l;
            high = h;
        }
        end = std::max(end, first + min_steps);
        if (end + min_steps > v.size()) end = v.size();  // a short remainder joins this step
        double energy = 0;
        for (size_t i = first; i < end; ++i) energy += v[i] * v[i];
        int amplitude = static_cast<int>(std::lround(
            std::sqrt(energy / static_cast<double>(end - first)) * kAndroidMaxAmplitude));
        if (amplitude < lowest) amplitude = 0;
        const auto ms = static_cast<int64_t>(
            std::lround(static_cast<double>(end - first) * HapticTrack::kStepS * 1e3));
        if (!steps.empty() && steps.back().amplitude == amplitude)
            steps.back().ms += ms;
        else
            steps.push_back({ms, amplitude});
        first = end;
    }
    return steps;
}

}  // namespace

int android_lowest_amplitude(double floor) {
    return std::clamp(static_cast<int>(std::ceil(floor * kAndroidMaxAmplitude - 1e-9)), 1,
                      kAndroidMaxAmplitude);
}

std::string android_waveform_text(const HapticTrack& track, double floor) {
    const int lowest = android_lowest_amplitude(floor);
    Json timings = Json::array(), amplitudes = Json::array();
    int64_t total_ms = 0;
    for (const Step& step : steps_of(track.intensity, lowest)) {
        timings.push_back(step.ms);
        amplitudes.push_back(step.amplitude);
        total_ms += step.ms;
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
        {"min_step_ms", kAndroidMinStepMs},
        {"lowest_amplitude", lowest},
        {"timings", timings},
        {"amplitudes", amplitudes},
        {"onsets_ms", onsets},
        {"onset_parts", parts},
        {"onset_strengths_db", strengths},
        {"metadata",
         {{"description", track.description()},
          {"felt_full_scale", std::stod(fmt::format("{:.4g}", track.felt_full_scale))}}}};
    return waveform.dump(1) + "\n";
}

}  // namespace tactus
