// --sync: how long the player's sound is held back so that each onset is heard when the pulse
// it triggers is felt (paper §6: the display's sound and vibration together). The delay is
// measured, not assumed: the onset decision comes a signal-dependent time after the onset (the
// flux must rise over the threshold, decided on the hop grid), then the post chain's
// look-ahead. An engine with the running settings hears sharp hits at phases spread over one
// hop; the median time from a hit to the first rise of its pulse is the delay. The settings
// change while `live` runs (OSC, the preset watcher): VibrationDelay measures again.
#pragma once

#include <optional>

#include "tactus/actuator/profile.hpp"
#include "tactus/params/params.hpp"

namespace tactus::live {

// The first rise of a pulse: where it first reaches this fraction of its peak.
inline constexpr double kPulseRiseFraction = 0.1;

// Setup or control thread (runs an engine offline for a few seconds of audio: milliseconds).
// At most max_vibration_delay_samples().
int vibration_delay_samples(const Settings& settings, double sample_rate_hz,
                            const std::optional<ActuatorProfile>& actuator);
// The longest delay the measurement can give: the time it leaves each hit's pulse to rise.
int max_vibration_delay_samples(double sample_rate_hz);

// The delay for the settings in force, measured again when they changed (a structural change,
// a preset reloaded, a live parameter such as envelope.attack_ms), at most every
// kRemeasurePeriodS so that a parameter swept over OSC costs little. Control thread (live's
// main loop), never the audio thread.
class VibrationDelay {
  public:
    static constexpr double kRemeasurePeriodS = 0.5;

    VibrationDelay(const Settings& settings, double sample_rate_hz,
                   std::optional<ActuatorProfile> actuator);
    int samples() const { return samples_; }
    // `running`: the settings now in force, at `now_s` (any steady clock, in seconds). True when
    // the delay changed.
    bool follow(const Settings& running, double now_s);

  private:
    Settings measured_;
    double sample_rate_hz_;
    std::optional<ActuatorProfile> actuator_;
    int samples_;
    double measured_at_s_ = -kRemeasurePeriodS;
};

}  // namespace tactus::live
