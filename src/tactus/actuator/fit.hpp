// The default mapping fitted to an actuator profile: what the engine runs instead of asking an
// actuator for what it cannot play (docs/perception.md "Actuators"; paper §4: the TFD's voice
// coils play the whole vibrotactile band, an LRA or an ERM does not).
//   frequency   the mapping.frequency range is fitted into the usable band, log-scaled: the
//               part of the mapping that lands on the band (widened kFrequencySpread times on a
//               log scale) is stretched onto it, so the features keep their order and a dull
//               kick and a bright snare stay at the band's two ends (150-235 Hz is a 1.57x
//               span on lra-175). An ERM's frequency follows its drive: it is fitted too, which
//               keeps the carrier whose envelope drives it above the envelope's smoothing.
//   square      a square's harmonics (3f and up) above the band are dropped: sine only.
//   hold        on an LRA, one frequency per pulse (mapping.frequency.hold): its sharp
//               resonance (Q 10 on lra-175, -10 dB at the band's edges) turns a few hertz of
//               the carrier into a decibel of displacement, so a pitch that wanders within a
//               pulse, or differs between two hits of one drum with where in the hit the onset
//               was decided, reorders their levels (through lra-175's model, hit gain -> felt
//               peak rho 0.73 without, 0.98 with; eval/actuators.py).
//   band        post.band_low_hz / band_high_hz within the usable band: the band-limit cuts what
//               the actuator cannot play (the compensation no longer lifts it there either);
//               not on an ERM, whose carrier only carries the intensity.
//   flutter     NPI flutter (2-40 Hz) is dropped when the actuator's response at its fastest
//               rate is below the compensation's reach (-ActuatorCompensation::kBoundDb), and
//               always on an ERM (its spin-up is slower than a flutter period).
//   pressure    NPIII pressure is dropped without DC capability (paper §5.4).
// The output ceiling at most the actuator's max drive and an ERM's intensity drive are the post
// chain's (post/post_chain.hpp); the note names them too. Pure functions, any thread.
#pragma once

#include <string>
#include <vector>

#include "tactus/actuator/profile.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

struct ActuatorFit {
    Settings settings;  // what the engine runs
    std::string note;   // one line naming what was fitted; empty when nothing was
};

// The band's log span is widened by this factor before the mapping's part landing on it is
// stretched onto the band: 1 keeps the in-band part of the mapping as it was (a clamp), larger
// keeps more of the range apart at the cost of a flatter slope. Tuned on the Sonic Pi kits
// through lra-175 (eval/actuators.py): 0.5 gave the same felt snare/kick ratios and a worse
// gain -> felt peak rho.
inline constexpr double kFrequencySpread = 1.0;
// The frequencies are placed this factor inside the band's edges: a pulse's spectrum has width
// (its envelope's), so a pulse right at an edge puts half its energy outside. A trade: 1.02
// keeps more of the snare/kick ratio felt through lra-175 (808: 1.41 against 1.38) but 74 %
// of the worst file's energy in the band against 82 % (Sonic Pi kits, eval/actuators.py).
inline constexpr double kEdgeMargin = 1.04;

ActuatorFit fit_to_actuator(const ActuatorProfile& actuator, const Settings& settings);

}  // namespace tactus
