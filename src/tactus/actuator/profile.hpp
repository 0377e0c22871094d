// An actuator profile: what the output stage drives and how a full-scale signal becomes skin
// displacement (paper §4; docs/perception.md "Actuators"). Read from TOML (actuators/*.toml):
//   name, type ("voice-coil", "lra", "erm"), description
//   displacement_um   peak displacement (um) for a full-scale sine at reference_hz
//   reference_hz      where displacement_um holds (the response is 0 dB there)
//   max_drive         largest safe drive, full scale (0-1]
//   dc                whether it can hold a sustained offset (a step, NPIII's pressure)
//   band_low_hz, band_high_hz   usable band; outside it the response falls rolloff_db_per_octave
//   rise_ms           time to reach full vibration (ERM spin-up; LRA ring-up)
//   [response] resonance_hz, q, kind ("low-pass": displacement of a driven mass-spring, flat
//              below resonance; "band-pass": narrow resonant peak), points = [[Hz, dB], ...]
//              (interpolated on log-frequency, flat beyond its ends; added to the resonance)
//   [erm] frequency_at_min_drive_hz, frequency_at_max_drive_hz  (ERM: frequency follows drive)
// Values in the shipped profiles are typical of the actuator class, not measurements: measure
// actuators loaded by skin, free-air responses differ a lot (docs/perception.md). Reading them from
// files: io/actuator_file.hpp.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tactus {

enum class ActuatorType { voice_coil, lra, erm };
enum class ResonanceKind { none, low_pass, band_pass };

struct ActuatorProfile {
    std::string name, description;
    ActuatorType type = ActuatorType::voice_coil;
    double displacement_um = 50.0;
    double reference_hz = 100.0;
    double max_drive = 1.0;
    bool dc = false;
    double band_low_hz = 20.0, band_high_hz = 1000.0;
    double rolloff_db_per_octave = 12.0;
    double rise_ms = 0.0;
    ResonanceKind resonance = ResonanceKind::none;
    double resonance_hz = 0.0, q = 1.0;
    std::vector<std::pair<double, double>> points;  // (Hz, dB), increasing Hz
    double erm_min_drive_hz = 0.0, erm_max_drive_hz = 0.0;

    bool operator==(const ActuatorProfile&) const = default;

    // Displacement response relative to reference_hz, dB (-inf at DC without DC capability).
    double response_db(double frequency_hz) const;
    // Peak displacement (um) of a full-scale sine at a frequency.
    double displacement_um_at(double frequency_hz) const;
    bool in_band(double frequency_hz) const {
        return frequency_hz >= band_low_hz && frequency_hz <= band_high_hz;
    }
};

inline constexpr std::string_view kActuatorTypeNames[] = {"voice-coil", "lra", "erm"};
std::string_view type_name(ActuatorType type);

constexpr std::string_view kDefaultActuator = "voice-coil";

// A table of (frequency Hz, dB) points, ascending, read at `f_hz`: linear in dB on a log-frequency
// axis between points, the end values beyond them, 0 dB for no points.
double interpolate_db(const std::vector<std::pair<double, double>>& points, double f_hz);

}  // namespace tactus
