// The one table of parameters: name, unit, range, default, curve and help for every setting of
// the pipeline. Presets, `--set`, and every front end (live engine, plugins, Pd, OSC, Python)
// read this table; nothing else declares a parameter.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace tactus {

enum class ParamType { real, integer, toggle, choice };  // the control a host shows
inline constexpr std::string_view kParamTypeNames[] = {"real", "integer", "toggle", "choice"};
enum class ParamCurve { lin, log };  // how a front end should lay the range out on a slider
// live: set while audio runs (no allocation, no lock), gliding over smoothing_ms;
// structural: the engine builds a new pipeline off the audio thread (buffer sizes, rates,
// routing), primes it and crossfades it in (engine/engine.hpp).
enum class ParamChange { live, structural };

enum class P : int;

struct ParamSpec {
    P param;                // the row's identifier inside the library (table order)
    uint32_t id;            // stable numeric id: hosts store automation and state by it; an id
                            // is never renumbered or reused (param_ids.txt, checked by a test)
    std::string_view key;   // dotted name, as in presets: "mapping.frequency.out_max"
    std::string_view unit;  // "dB", "Hz", "ms", "" ...
    ParamType type;         // integer, toggle and choice values are whole numbers
    double min;
    double max;
    double default_value;
    ParamCurve curve;
    ParamChange change;
    double smoothing_ms;  // live: the time a change glides over (0: at once)
    std::string_view help;
    std::span<const std::string_view> choices = {};  // toggle, choice: the value is the index
};

// Features a mapping can read (analysis outputs), in the order of FeatureSource.
inline constexpr std::array<std::string_view, 9> kFeatureSourceNames = {
    "loudness_db",      "brightness_hz", "noisiness", "tonality",         "pitch_hz",
    "pitch_confidence", "onset_odf",     "hit_db",    "hit_brightness_hz"};
enum class FeatureSource {
    loudness_db,
    brightness_hz,
    noisiness,
    tonality,
    pitch_hz,
    pitch_confidence,
    onset_odf,
    hit_db,            // what the latest hit added above what was sounding, dB
    hit_brightness_hz  // its brightness
};

// lin: output linear in input. log: input and output on logarithmic scales (equal input ratios
// give equal output ratios: a frequency scale). exp: linear input, logarithmic output (dB in,
// amplitude out).
inline constexpr std::array<std::string_view, 3> kCurveNames = {"lin", "log", "exp"};
enum class MappingCurve { lin, log, exp };

// On/off settings (ParamType::toggle): the value is 0 (off) or 1 (on).
inline constexpr std::array<std::string_view, 2> kSwitchNames = {"off", "on"};

// Parameter identifiers inside the library, in table order (not stable: ParamSpec::id is).
enum class P : int {
    analysis_window_ms,
    analysis_hop_ms,
    loudness_window_ms,
    pitch_min_hz,
    pitch_max_hz,
    pitch_threshold,
    onset_window_ms,
    onset_threshold,
    onset_ratio,
    onset_history_ms,
    onset_min_interval_ms,
    mapping_gate_db,
#define TACTUS_MAPPING_IDS(name)                                                               \
    name##_source, name##_in_min, name##_in_max, name##_out_min, name##_out_max, name##_curve, \
        name##_smoothing_ms
    TACTUS_MAPPING_IDS(amplitude),
    TACTUS_MAPPING_IDS(frequency),
    TACTUS_MAPPING_IDS(square_mix),
    envelope_attack_ms,
    envelope_decay_ms,
    envelope_sustain,
    flutter_weight,
    flutter_equalize,
    TACTUS_MAPPING_IDS(flutter_level),
    TACTUS_MAPPING_IDS(flutter_rate),
    pressure_weight,
    pressure_steps,
    TACTUS_MAPPING_IDS(pressure_level),
#undef TACTUS_MAPPING_IDS
    actuator_dc,
    post_band_low_hz,
    post_band_high_hz,
    post_flutter_low_hz,
    post_flutter_peak_db,
    post_flatten_strength,
    post_flatten_range_db,
    post_flatten_level_db,
    post_drive_db,
    post_limiter_threshold_db,
    post_ceiling_db,
    post_lookahead_ms,
    post_release_ms,
    perception_contact_area_cm2,
    frequency_hold,
    frequency_settle_ms,
    brightness_max_hz,
    parts_settle_ms,
    onset_high_weight,
    onset_low_weight,
#define TACTUS_PART_IDS(part) \
    parts_##part##_gain_db, parts_##part##_brightness_hz, parts_##part##_decay_ms
    TACTUS_PART_IDS(kick),
    TACTUS_PART_IDS(snare),
    TACTUS_PART_IDS(hat),
    TACTUS_PART_IDS(other),
#undef TACTUS_PART_IDS
    parts_drum_min,
    parts_route_min,
    count
};

std::span<const ParamSpec> param_table();
const ParamSpec& spec(P id);
std::optional<P> find_param(std::string_view key);
std::optional<P> find_param(uint32_t stable_id);
// The known key closest to `key` (edit distance), for "did you mean" messages.
std::string nearest_param(std::string_view key);

// The key with '_' for '.' ("envelope_decay_ms"): the name where dots are not allowed (LV2
// symbols, Vamp identifiers, Python attributes).
std::string identifier_of(const ParamSpec& spec);

// "5 to 5000 ms": a parameter's allowed range and unit, for messages.
std::string range_text(const ParamSpec& spec);

// A value for every parameter, starting at the table's defaults.
class Settings {
  public:
    Settings();
    double operator[](P id) const { return values_[static_cast<int>(id)]; }
    // Sets a value after checking its range; throws std::invalid_argument naming the key.
    void set(P id, double value);
    // A value set() has accepted (on another thread, say): no check, never throws.
    void assign(P id, double value) noexcept { values_[static_cast<int>(id)] = value; }
    // Parses "value" for a key: a number for numeric parameters, a name for choices.
    void set_from_text(P id, std::string_view text);
    std::string text_of(P id) const;
    bool operator==(const Settings&) const = default;

  private:
    std::array<double, static_cast<int>(P::count)> values_{};
};

}  // namespace tactus
