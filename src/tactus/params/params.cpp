#include "tactus/params/params.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "tactus/core/nearest.hpp"
#include "tactus/core/printable.hpp"
#include "tactus/params/mapping_rows.hpp"
#include "tactus/params/part_rows.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {

using enum ParamType;
using enum ParamChange;
using enum ParamCurve;

using params_detail::joined_rows;
using params_detail::mapping_rows;
using params_detail::part_rows;

constexpr std::span<const std::string_view> kSwitch{kSwitchNames};

// The default mapping reads what each hit added above what was sounding (its loudness and its
// brightness; analysis/hit_analysis.hpp), so a mix's bed neither strengthens nor brightens it;
// presets/tfd.toml is the paper's, on the whole mix.
constexpr double kHitDb = static_cast<double>(FeatureSource::hit_db);
constexpr double kHitBrightness = static_cast<double>(FeatureSource::hit_brightness_hz);

// Channel bands (paper Table 1) that bound the flutter and pressure settings.
constexpr double kNpiHighHz = perception::info(perception::Channel::NPI).range_high_hz;
constexpr double kNpiLowHz = perception::info(perception::Channel::NPI).range_low_hz;

// clang-format off
constexpr auto kTable = joined_rows(
    std::to_array<ParamSpec>({
    // Analysis (paper §6, Figure 4: feature extraction).
    {P::analysis_window_ms, 1, "analysis.window_ms", "ms", real, 5, 100, 24, log, structural, 0,
     "STFT window for brightness, noisiness (nearest fast FFT size at the 16 kHz analysis rate)"},
    {P::analysis_hop_ms, 2, "analysis.hop_ms", "ms", real, 0.5, 20, 1.45, log, structural, 0,
     "time between analysis frames; control rate of the vibration program"},
    {P::loudness_window_ms, 3, "loudness.window_ms", "ms", real, 2, 400, 10, log, structural, 0,
     "integration window of the K-weighted loudness (ITU-R BS.1770 filter, short window)"},
    {P::pitch_min_hz, 4, "pitch.min_hz", "Hz", real, 30, 1000, 50, log, structural, 0,
     "lowest f0 the pitch tracker reports"},
    {P::pitch_max_hz, 5, "pitch.max_hz", "Hz", real, 100, 4000, 1500, log, structural, 0,
     "highest f0 the pitch tracker reports"},
    {P::pitch_threshold, 6, "pitch.threshold", "", real, 0.01, 0.5, 0.15, lin, live, 0,
     "YIN absolute threshold on the cumulative-mean-normalised difference"},
    {P::onset_window_ms, 7, "onset.window_ms", "ms", real, 2, 50, 10, log, structural, 0,
     "STFT window of the onset detection function (short, for low latency; nearest fast FFT size)"},
    {P::onset_threshold, 8, "onset.threshold", "", real, 0, 100, 11, lin, live, 0,
     "fixed part of the adaptive threshold on the log spectral flux"},
    {P::onset_ratio, 9, "onset.ratio", "", real, 0, 10, 1.25, lin, live, 0,
     "multiple of the recent median flux the flux must exceed to be an onset"},
    {P::onset_history_ms, 10, "onset.history_ms", "ms", real, 10, 2000, 60, log, structural, 0,
     "length of the flux history whose median the adaptive threshold takes"},
    {P::onset_min_interval_ms, 11, "onset.min_interval_ms", "ms", real, 5, 500, 50, log, live, 0,
     "shortest time between two onsets"},
    // Mapping (paper §6): features -> the vibration program.
    {P::mapping_gate_db, 12, "mapping.gate_db", "dB", real, -120, 0, -70, lin, live, 20,
     "below this loudness the vibration is silent and mapped parameters hold"},
    }),
    // The mapping groups: seven rows each (source, in_min ... smoothing_ms; mapping_rows.hpp).
    mapping_rows<"amplitude", "amplitude", " (full scale 1)", "amplitude">(
     {.source = P::amplitude_source, .source_id = 13, .source_default = kHitDb,
      .source_help = "feature mapped to vibration amplitude", .in_min = -60, .in_max = 0,
      .out_unit = "", .out_low = 0, .out_high = 1, .out_curve = lin, .out_min = 0.03, .out_max = 1,
      .curve = 2, .smoothing_max_ms = 1000, .smoothing_ms = 0}),
    mapping_rows<"frequency", "vibration frequency", "", "frequency">(
     {.source = P::frequency_source, .source_id = 20, .source_default = kHitBrightness,
      .source_help = "feature mapped to vibration frequency", .in_min = 100, .in_max = 300,
      .out_unit = "Hz", .out_low = 1, .out_high = 1000, .out_curve = log, .out_min = 40, .out_max = 400,
      .curve = 1, .smoothing_max_ms = 1000, .smoothing_ms = 5}),
    mapping_rows<"square_mix", "square mix", "", "square mix">(
     {.source = P::square_mix_source, .source_id = 27, .source_default = 3,
      .source_help = "feature mapped to the sine (0) / square (1) mix", .in_min = 0.3, .in_max = 0.9,
      .out_unit = "", .out_low = 0, .out_high = 1, .out_curve = lin, .out_min = 0, .out_max = 1,
      .curve = 0, .smoothing_max_ms = 1000, .smoothing_ms = 20}),
    std::to_array<ParamSpec>({
    // Synthesis: AD envelope retriggered by onsets (paper §6, bonk~ driving an envelope).
    {P::envelope_attack_ms, 34, "envelope.attack_ms", "ms", real, 0.1, 100, 1, log, live, 0,
     "rise time from trigger to peak"},
    {P::envelope_decay_ms, 35, "envelope.decay_ms", "ms", real, 5, 5000, 150, log, live, 0,
     "time from peak to -60 dB below it (towards the sustain level)"},
    {P::envelope_sustain, 36, "envelope.sustain", "", real, 0, 1, 0, lin, live, 0,
     "level the envelope decays to, so sustained sounds stay felt (0 = discrete pulses)"},
    // Synthesis: one component per further channel of touch (paper §5.2, §5.4). Off by default.
    {P::flutter_weight, 37, "flutter.weight", "", real, 0, 1, 0, lin, live, 20,
     "NPI flutter (2-40 Hz) level at mapped level 1, full scale (0 = off; paper 5.2)"},
    {P::flutter_equalize, 38, "flutter.equalize", "", toggle, 0, 1, 0, lin, live, 20,
     "scale the flutter by the P/NPI innervation ratio 21/140 (-16.5 dB) so both channels are "
     "engaged about equally loudly (paper 5.2)", kSwitch},
    }),
    mapping_rows<"flutter_level", "flutter level", " (0 ... 1)", "flutter level">(
     {.source = P::flutter_level_source, .source_id = 39, .source_default = 0,
      .source_help = "feature mapped to the flutter level", .in_min = -60, .in_max = 0,
      .out_unit = "", .out_low = 0, .out_high = 1, .out_curve = lin, .out_min = 0.03, .out_max = 1,
      .curve = 2, .smoothing_max_ms = 1000, .smoothing_ms = 40}),
    mapping_rows<"flutter_rate", "flutter rate", " (inside NPI's 2-40 Hz)", "flutter rate">(
     {.source = P::flutter_rate_source, .source_id = 46, .source_default = 1,
      .source_help = "feature mapped to the flutter rate", .in_min = 100, .in_max = 6000,
      .out_unit = "Hz", .out_low = kNpiLowHz, .out_high = kNpiHighHz, .out_curve = log, .out_min = 8,
      .out_max = 30, .curve = 1, .smoothing_max_ms = 1000, .smoothing_ms = 20}),
    std::to_array<ParamSpec>({
    {P::pressure_weight, 53, "pressure.weight", "", real, 0, 0.5, 0, lin, live, 20,
     "NPIII pressure offset at mapped level 1, as a fraction of the output ceiling; the vibration "
     "gives up this much headroom (0 = off; needs actuator.dc; paper 5.4)"},
    {P::pressure_steps, 54, "pressure.steps", "", integer, 0, 8, 0, lin, live, 0,
     "sustained pressure levels above 0, rounded (0 = continuous; paper 5.4 step functions)"},
    }),
    mapping_rows<"pressure_level", "pressure level", " (0 ... 1)", "pressure level">(
     {.source = P::pressure_level_source, .source_id = 55, .source_default = 0,
      .source_help = "feature mapped to the pressure level", .in_min = -60, .in_max = 0,
      .out_unit = "", .out_low = 0, .out_high = 1, .out_curve = lin, .out_min = 0, .out_max = 1,
      .curve = 0, .smoothing_max_ms = 5000, .smoothing_ms = 300}),
    std::to_array<ParamSpec>({
    // Actuator capabilities.
    {P::actuator_dc, 62, "actuator.dc", "", toggle, 0, 1, 0, lin, structural, 0,
     "the actuator holds a sustained offset (DC); without it the pressure component is silent "
     "(paper 5.4)", kSwitch},
    // Post-processing in the paper's order (§6).
    {P::post_band_low_hz, 63, "post.band_low_hz", "Hz", real, 1, 200, 30, log, structural, 0,
     "lower edge of the vibrotactile band"},
    {P::post_band_high_hz, 64, "post.band_high_hz", "Hz", real, 200, 2000, 1000, log, structural, 0,
     "upper edge of the vibrotactile band; also the oscillator's harmonic limit"},
    {P::post_flutter_low_hz, 65, "post.flutter_low_hz", "Hz", real, 0.5, 30, 1, log, structural, 0,
     "high-pass edge of the last band-limit when the flutter is on (NPI starts at 2 Hz)"},
    {P::post_flutter_peak_db, 66, "post.flutter_peak_db", "dB", real, -12, 12, 0, lin, live, 20,
     "peaking filter at 30 Hz on the flutter, for NPI's notch (paper 5.2 note 4; 0 = none)"},
    {P::post_flatten_strength, 67, "post.flatten_strength", "", real, 0, 1, 1, lin, live, 50,
     "fraction of the P-channel threshold curve the flattening filter compensates"},
    {P::post_flatten_range_db, 68, "post.flatten_range_db", "dB", real, 0, 40, 30, lin, live, 50,
     "largest level difference the flattening filter applies across the band"},
    {P::post_flatten_level_db, 69, "post.flatten_level_db", "dB", real, 0, 70, 0, lin, live, 50,
     "sensation level whose equal-sensation contour is flattened (0 = threshold curve; contours "
     "flatten as level rises)"},
    {P::post_drive_db, 70, "post.drive_db", "dB", real, -40, 40, 12, lin, live, 20,
     "gain into the peak limiter"},
    {P::post_limiter_threshold_db, 71, "post.limiter_threshold_db", "dB", real, -40, 0, -6, lin, live, 20,
     "level, relative to the ceiling, where the limiter's soft knee starts"},
    {P::post_ceiling_db, 72, "post.ceiling_db", "dB", real, -40, 0, 0, lin, live, 20,
     "hard ceiling of the output peak, dB full scale"},
    {P::post_lookahead_ms, 73, "post.lookahead_ms", "ms", real, 0.1, 20, 0.3, log, structural, 0,
     "limiter look-ahead (adds its length to the latency)"},
    {P::post_release_ms, 74, "post.release_ms", "ms", real, 1, 2000, 80, log, live, 0,
     "limiter gain recovery time constant"},
    // Perception model (docs/perception.md): conditions the thresholds depend on.
    {P::perception_contact_area_cm2, 75, "perception.contact_area_cm2", "cm2", real, 0.005, 20, 2.9, log, live, 50,
     "skin contact area of the actuator (P channel spatial summation; 2.9 = reference curves)"},
    // Mapping, continued: one frequency per pulse (paper §6: bonk~ drives "discrete vibrotactile
    // pulses" whose pitch is the hit's brightness, so kick and snare are told apart).
    {P::frequency_hold, 76, "mapping.frequency.hold", "", toggle, 0, 1, 0, lin, live, 0,
     "one frequency per pulse: from each onset the frequency follows the mapping unsmoothed "
     "for settle_ms, then holds until the next onset (off: smoothed throughout)", kSwitch},
    {P::frequency_settle_ms, 77, "mapping.frequency.settle_ms", "ms", real, 0, 100, 30, lin, live, 0,
     "with hold on: how long after an onset the pulse's frequency follows the mapping before "
     "it holds (0: the onset frame's)"},
    // Analysis: the band the brightness reads (analysis/brightness.hpp).
    {P::brightness_max_hz, 78, "brightness.max_hz", "Hz", real, 200, 8000, 1500, log, live, 0,
     "highest frequency the brightness centroid reads: a drum's body, not its beater click or "
     "snare wires (8000: the whole 16 kHz analysis band)"},
    // Analysis: what each hit adds and its drum part (analysis/hit_analysis.hpp).
    {P::parts_settle_ms, 79, "parts.settle_ms", "ms", real, 1, 30, 20, lin, live, 0,
     "time from a hit's onset to the decision of its drum part (kick, snare, hat, other): "
     "longer reads more of the hit"},
    {P::onset_high_weight, 80, "onset.high_weight", "", real, 0, 200, 30, lin, live, 0,
     "weight, in spectrum bins, of the rise of the input above 6 kHz in the onset detection "
     "function (hats; 0 = the analysis band alone)"},
    {P::onset_low_weight, 81, "onset.low_weight", "", real, 0, 200, 5, lin, live, 0,
     "weight, in spectrum bins, of the rise of the input below 150 Hz in the onset detection "
     "function (kicks; 0 = the spectrum's own bins alone)"},
    }),
    // Mapping by drum part (analysis/hit_analysis.hpp, mapping/mapper.hpp): each part's pulse
    // its own strength, pitch and length once its part is decided (part_rows.hpp).
    part_rows<"kick", "a kick">(P::parts_kick_gain_db, 82),
    part_rows<"snare", "a snare">(P::parts_snare_gain_db, 85),
    part_rows<"hat", "a hi-hat or cymbal">(P::parts_hat_gain_db, 88),
    part_rows<"other", "any other onset (bass, chords, voice)">(P::parts_other_gain_db, 91),
    std::to_array<ParamSpec>({
    // Analysis: a drum's onset or another sound's (analysis/onset_rises.hpp).
    {P::parts_drum_min, 94, "parts.drum_min", "", real, 0, 1, 0, lin, live, 0,
     "least probability, by how its bands rose, that an onset is a drum's for it to wait for "
     "its drum part; below it the onset is `other` at once, before its pulse starts (0 = off; "
     "with parts.other.gain_db = -60: drums only)"},
    // Routing by drum part (engine/route.hpp): the hits a part route plays. Tuned on the music
    // corpus's tuning parts, the least value keeping 85 % of the other part's hits 10 dB under
    // each output (eval/routes.py); the held-out parts' trade is in eval/routes.md.
    {P::parts_route_min, 95, "parts.route_min", "", real, 0, 1, 0.35, lin, live, 0,
     "least probability, by the part model, that a hit is one of a part route's parts for the "
     "route to play it too when it is named another part (1 = only the hits named its parts)"},
    }));
// clang-format on

// Row i describes P(i), and no two rows share a stable id: checked at compile time, so the
// table's order and the enum cannot drift apart.
constexpr bool rows_in_enum_order() {
    for (size_t i = 0; i < std::size(kTable); ++i)
        if (kTable[i].param != static_cast<P>(i)) return false;
    return std::size(kTable) == static_cast<size_t>(P::count);
}
static_assert(rows_in_enum_order(), "one table row per P, in P's order");
constexpr bool ids_unique() {
    for (size_t i = 0; i < std::size(kTable); ++i)
        for (size_t j = i + 1; j < std::size(kTable); ++j)
            if (kTable[i].id == kTable[j].id) return false;
    return true;
}
static_assert(ids_unique(), "stable ids are unique");

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

std::optional<P> find_param(uint32_t stable_id) {
    for (const ParamSpec& s : kTable)
        if (s.id == stable_id) return s.param;
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

std::string identifier_of(const ParamSpec& spec) {
    std::string identifier(spec.key);
    std::replace(identifier.begin(), identifier.end(), '.', '_');
    return identifier;
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
    if (s.type != ParamType::real) value = std::round(value);
    values_[static_cast<int>(id)] = value;
}

void Settings::set_from_text(P id, std::string_view text) {
    const ParamSpec& s = spec(id);
    if (!s.choices.empty()) {
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
    if (!s.choices.empty()) return std::string(s.choices[static_cast<size_t>(v)]);
    return fmt::format("{}", v);
}

}  // namespace tactus
