// --sync: how long the player's sound is held back so that each onset is heard when the pulse
// it triggers is felt (paper §6: the display's sound and vibration together). The delay is
// measured, not assumed: the onset decision comes a signal-dependent time after the onset (the
// flux must rise over the threshold, decided on the hop grid), then the post chain's
// look-ahead. An engine with the running settings hears sharp hits at phases spread over one
// hop; the median time from a hit to the first rise of its pulse is the delay.
#pragma once

#include <optional>

#include "tactus/actuator/profile.hpp"
#include "tactus/params/params.hpp"

namespace tactus::live {

// The first rise of a pulse: where it first reaches this fraction of its peak.
inline constexpr double kPulseRiseFraction = 0.1;

// Setup thread (runs an engine offline for a few seconds of audio: milliseconds).
int vibration_delay_samples(const Settings& settings, double sample_rate_hz,
                            const std::optional<ActuatorProfile>& actuator);

}  // namespace tactus::live
