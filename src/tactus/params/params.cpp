#include "tactus/params/params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "tactus/perception/channels.hpp"
#include "tactus/core/printable.hpp"

namespace tactus {
namespace {

using enum ParamKind;
using enum ParamCurve;

constexpr std::span<const std::string_view> kSources{kFeatureSourceNames};
constexpr std::span<const std::string_view> kCurves{kCurveNames};
constexpr std::span<const std::string_view> kSwitch{kSwitchNames};

constexpr double kLastSource = kFeatureSourceNames.size() - 1;
constexpr double kLastCurve = kCurveNames.size() - 1;

// Channel bands (paper Table 1) that bound the flutter and pressure settings.
constexpr double kNpiHighHz = perception::info(perception::Channel::NPI).range_high_hz;
constexpr double kNpiLowHz = perception::info(perception::Channel::NPI).range_low_hz;

// clang-format off
const ParamSpec kTable[] = {
    // Analysis (paper §6, Figure 4: feature extraction).
    {"analysis.window_ms", "ms", number, 5, 100, 23.2, log,
     "STFT window for brightness, noisiness (nearest power of two in samples)"},
    {"analysis.hop_ms", "ms", number, 0.5, 20, 2.9, log,
     "time between analysis frames; control rate of the vibration program"},
    {"loudness.window_ms", "ms", number, 2, 400, 10, log,
     "integration window of the K-weighted loudness (ITU-R BS.1770 filter, short window)"},
    {"pitch.min_hz", "Hz", number, 30, 1000, 50, log, "lowest f0 the pitch tracker reports"},
    {"pitch.max_hz", "Hz", number, 100, 4000, 1500, log, "highest f0 the pitch tracker reports"},
    {"pitch.threshold", "", number, 0.01, 0.5, 0.15, lin,
     "YIN absolute threshold on the cumulative-mean-normalised difference"},
    {"onset.window_ms", "ms", number, 2, 50, 5.8, log,
     "STFT window of the onset detection function (short, for low latency; nearest power of two)"},
    {"onset.threshold", "", number, 0, 100, 10, lin,
     "fixed part of the adaptive threshold on the log spectral flux"},
    {"onset.ratio", "", number, 0, 10, 1.25, lin,
     "multiple of the recent mean flux the flux must exceed to be an onset"},
    {"onset.history_ms", "ms", number, 10, 2000, 60, log,
     "length of the flux history the adaptive threshold averages"},
    {"onset.min_interval_ms", "ms", number, 5, 500, 50, log,
     "shortest time between two onsets"},
    // Mapping (paper §6): features -> the vibration program.
    {"mapping.gate_db", "dB", number, -120, 0, -70, lin,
     "below this loudness the vibration is silent and mapped parameters hold"},
    {"mapping.amplitude.source", "", choice, 0, kLastSource, 0, lin,
     "feature mapped to vibration amplitude", kSources},
    {"mapping.amplitude.in_min", "", number, -1e6, 1e6, -60, lin, "source value mapped to out_min"},
    {"mapping.amplitude.in_max", "", number, -1e6, 1e6, 0, lin, "source value mapped to out_max"},
    {"mapping.amplitude.out_min", "", number, 0, 1, 0.03, lin, "amplitude at in_min (full scale 1)"},
    {"mapping.amplitude.out_max", "", number, 0, 1, 1, lin, "amplitude at in_max (full scale 1)"},
    {"mapping.amplitude.curve", "", choice, 0, kLastCurve, 2, lin,
     "lin, log (ratio to ratio) or exp (dB to amplitude)", kCurves},
    {"mapping.amplitude.smoothing_ms", "ms", number, 0, 1000, 0, lin,
     "one-pole time constant applied to the mapped amplitude"},
    {"mapping.frequency.source", "", choice, 0, kLastSource, 1, lin,
     "feature mapped to vibration frequency", kSources},
    {"mapping.frequency.in_min", "", number, -1e6, 1e6, 70, lin, "source value mapped to out_min"},
    {"mapping.frequency.in_max", "", number, -1e6, 1e6, 2000, lin, "source value mapped to out_max"},
    {"mapping.frequency.out_min", "Hz", number, 1, 1000, 40, log, "vibration frequency at in_min"},
    {"mapping.frequency.out_max", "Hz", number, 1, 1000, 400, log, "vibration frequency at in_max"},
    {"mapping.frequency.curve", "", choice, 0, kLastCurve, 1, lin,
     "lin, log (ratio to ratio) or exp (dB to amplitude)", kCurves},
    {"mapping.frequency.smoothing_ms", "ms", number, 0, 1000, 5, lin,
     "one-pole time constant applied to the mapped frequency"},
    {"mapping.square_mix.source", "", choice, 0, kLastSource, 3, lin,
     "feature mapped to the sine (0) / square (1) mix", kSources},
    {"mapping.square_mix.in_min", "", number, -1e6, 1e6, 0.3, lin, "source value mapped to out_min"},
    {"mapping.square_mix.in_max", "", number, -1e6, 1e6, 0.9, lin, "source value mapped to out_max"},
    {"mapping.square_mix.out_min", "", number, 0, 1, 0, lin, "square mix at in_min"},
    {"mapping.square_mix.out_max", "", number, 0, 1, 1, lin, "square mix at in_max"},
    {"mapping.square_mix.curve", "", choice, 0, kLastCurve, 0, lin,
     "lin, log (ratio to ratio) or exp (dB to amplitude)", kCurves},
    {"mapping.square_mix.smoothing_ms", "ms", number, 0, 1000, 20, lin,
     "one-pole time constant applied to the mapped square mix"},
    // Synthesis: AD envelope retriggered by onsets (paper §6, bonk~ driving an envelope).
    {"envelope.attack_ms", "ms", number, 0.1, 100, 1, log, "rise time from trigger to peak"},
    {"envelope.decay_ms", "ms", number, 5, 5000, 150, log,
     "time from peak to -60 dB below it (towards the sustain level)"},
    {"envelope.sustain", "", number, 0, 1, 0, lin,
     "level the envelope decays to, so sustained sounds stay felt (0 = discrete pulses)"},
    // Synthesis: one component per further channel of touch (paper §5.2, §5.4). Off by default.
    {"flutter.weight", "", number, 0, 1, 0, lin,
     "NPI flutter (2-40 Hz) level at mapped level 1, full scale (0 = off; paper 5.2)"},
    {"flutter.equalize", "", choice, 0, 1, 0, lin,
     "scale the flutter by the P/NPI innervation ratio 21/140 (-16.5 dB) so both channels are "
     "engaged about equally loudly (paper 5.2)", kSwitch},
    {"mapping.flutter_level.source", "", choice, 0, kLastSource, 0, lin,
     "feature mapped to the flutter level", kSources},
    {"mapping.flutter_level.in_min", "", number, -1e6, 1e6, -60, lin, "source value mapped to out_min"},
    {"mapping.flutter_level.in_max", "", number, -1e6, 1e6, 0, lin, "source value mapped to out_max"},
    {"mapping.flutter_level.out_min", "", number, 0, 1, 0.03, lin, "flutter level at in_min (0 ... 1)"},
    {"mapping.flutter_level.out_max", "", number, 0, 1, 1, lin, "flutter level at in_max (0 ... 1)"},
    {"mapping.flutter_level.curve", "", choice, 0, kLastCurve, 2, lin,
     "lin, log (ratio to ratio) or exp (dB to amplitude)", kCurves},
    {"mapping.flutter_level.smoothing_ms", "ms", number, 0, 1000, 40, lin,
     "one-pole time constant applied to the mapped flutter level"},
    {"mapping.flutter_rate.source", "", choice, 0, kLastSource, 1, lin,
     "feature mapped to the flutter rate", kSources},
    {"mapping.flutter_rate.in_min", "", number, -1e6, 1e6, 100, lin, "source value mapped to out_min"},
    {"mapping.flutter_rate.in_max", "", number, -1e6, 1e6, 6000, lin, "source value mapped to out_max"},
    {"mapping.flutter_rate.out_min", "Hz", number, kNpiLowHz, kNpiHighHz, 8, log,
     "flutter rate at in_min (inside NPI's 2-40 Hz)"},
    {"mapping.flutter_rate.out_max", "Hz", number, kNpiLowHz, kNpiHighHz, 30, log,
     "flutter rate at in_max (inside NPI's 2-40 Hz)"},
    {"mapping.flutter_rate.curve", "", choice, 0, kLastCurve, 1, lin,
     "lin, log (ratio to ratio) or exp (dB to amplitude)", kCurves},
    {"mapping.flutter_rate.smoothing_ms", "ms", number, 0, 1000, 20, lin,
     "one-pole time constant applied to the mapped flutter rate"},
    {"pressure.weight", "", number, 0, 0.5, 0, lin,
     "NPIII pressure offset at mapped level 1, as a fraction of the output ceiling; the vibration "
     "gives up this much headroom (0 = off; needs actuator.dc; paper 5.4)"},
    {"pressure.steps", "", number, 0, 8, 0, lin,
     "sustained pressure levels above 0, rounded (0 = continuous; paper 5.4 step functions)"},
    {"mapping.pressure_level.source", "", choice, 0, kLastSource, 0, lin,
     "feature mapped to the pressure level", kSources},
    {"mapping.pressure_level.in_min", "", number, -1e6, 1e6, -60, lin, "source value mapped to out_min"},
    {"mapping.pressure_level.in_max", "", number, -1e6, 1e6, 0, lin, "source value mapped to out_max"},
    {"mapping.pressure_level.out_min", "", number, 0, 1, 0, lin, "pressure level at in_min (0 ... 1)"},
    {"mapping.pressure_level.out_max", "", number, 0, 1, 1, lin, "pressure level at in_max (0 ... 1)"},
    {"mapping.pressure_level.curve", "", choice, 0, kLastCurve, 0, lin,
     "lin, log (ratio to ratio) or exp (dB to amplitude)", kCurves},
    {"mapping.pressure_level.smoothing_ms", "ms", number, 0, 5000, 300, lin,
     "one-pole time constant applied to the mapped pressure level"},
    // Actuator capabilities.
    {"actuator.dc", "", choice, 0, 1, 0, lin,
     "the actuator holds a sustained offset (DC); without it the pressure component is silent "
     "(paper 5.4)", kSwitch},
    // Post-processing in the paper's order (§6).
    {"post.band_low_hz", "Hz", number, 1, 200, 30, log, "lower edge of the vibrotactile band"},
    {"post.band_high_hz", "Hz", number, 200, 2000, 1000, log,
     "upper edge of the vibrotactile band; also the oscillator's harmonic limit"},
    {"post.flutter_low_hz", "Hz", number, 0.5, 30, 1, log,
     "high-pass edge of the last band-limit when the flutter is on (NPI starts at 2 Hz)"},
    {"post.flutter_peak_db", "dB", number, -12, 12, 0, lin,
     "peaking filter at 30 Hz on the flutter, for NPI's notch (paper 5.2 note 4; 0 = none)"},
    {"post.flatten_strength", "", number, 0, 1, 1, lin,
     "fraction of the P-channel threshold curve the flattening filter compensates"},
    {"post.flatten_range_db", "dB", number, 0, 40, 30, lin,
     "largest level difference the flattening filter applies across the band"},
    {"post.flatten_level_db", "dB", number, 0, 70, 0, lin,
     "sensation level whose equal-sensation contour is flattened (0 = threshold curve; contours "
     "flatten as level rises)"},
    {"post.drive_db", "dB", number, -40, 40, 12, lin, "gain into the peak limiter"},
    {"post.limiter_threshold_db", "dB", number, -40, 0, -6, lin,
     "level, relative to the ceiling, where the limiter's soft knee starts"},
    {"post.ceiling_db", "dB", number, -40, 0, 0, lin,
     "hard ceiling of the output peak, dB full scale"},
    {"post.lookahead_ms", "ms", number, 0.1, 20, 1.5, log, "limiter look-ahead (adds latency)"},
    {"post.release_ms", "ms", number, 1, 2000, 80, log, "limiter gain recovery time constant"},
    // Perception model (perception.md): conditions the thresholds depend on.
    {"perception.contact_area_cm2", "cm2", number, 0.005, 20, 2.9, log,
     "skin contact area of the actuator (P channel spatial summation; 2.9 = reference curves)"},
};
// clang-format on

static_assert(std::size(kTable) == static_cast<size_t>(P::count),
              "one table row per parameter identifier");

size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::span<const ParamSpec> param_table() {
    return kTable;
}

const ParamSpec& spec(P id) {
    return kTable[static_cast<int>(id)];
}

std::optional<P> find_param(std::string_view key) {
    for (size_t i = 0; i < std::size(kTable); ++i)
        if (kTable[i].key == key) return static_cast<P>(i);
    return std::nullopt;
}

std::string nearest_param(std::string_view key) {
    // Edit distance costs length x length per key: a megabyte of typing must not hang the
    // suggestion, and past the longest key's length it cannot change much.
    constexpr size_t kComparedChars = 64;
    key = key.substr(0, kComparedChars);
    std::string_view best;
    size_t best_distance = SIZE_MAX;
    for (const auto& s : kTable) {
        const size_t d = edit_distance(key, s.key);
        if (d < best_distance) best_distance = d, best = s.key;
    }
    return std::string(best);
}

std::string range_text(const ParamSpec& s) {
    return fmt::format("{} to {}{}{}", s.min, s.max, s.unit.empty() ? "" : " ", s.unit);
}

Settings::Settings() {
    for (size_t i = 0; i < std::size(kTable); ++i) values_[i] = kTable[i].default_value;
}

void Settings::set(P id, double value) {
    const ParamSpec& s = spec(id);
    if (!std::isfinite(value) || value < s.min || value > s.max) {
        throw std::invalid_argument(
            fmt::format("{} = {} is out of range: allowed {}", s.key, value, range_text(s)));
    }
    if (s.kind == ParamKind::choice) value = std::round(value);
    values_[static_cast<int>(id)] = value;
}

void Settings::set_from_text(P id, std::string_view text) {
    const ParamSpec& s = spec(id);
    if (s.kind == ParamKind::choice) {
        for (size_t i = 0; i < s.choices.size(); ++i)
            if (s.choices[i] == text) return set(id, static_cast<double>(i));
        std::string allowed;
        for (auto c : s.choices) allowed += (allowed.empty() ? "" : ", ") + std::string(c);
        throw std::invalid_argument(
            fmt::format("{} = '{}' is not one of: {}", s.key, printable(text), allowed));
    }
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw std::invalid_argument(
            fmt::format("{} = '{}' is not a number", s.key, printable(text)));
    set(id, value);
}

std::string Settings::text_of(P id) const {
    const ParamSpec& s = spec(id);
    const double v = (*this)[id];
    if (s.kind == ParamKind::choice) return std::string(s.choices[static_cast<size_t>(v)]);
    return fmt::format("{}", v);
}

}  // namespace tactus
