// The weakest drive of an actuator that is felt at all (0 ... 1 of its largest safe drive,
// max_drive): the P-channel detection threshold (perception/threshold.hpp: at the contact area,
// with full temporal summation, 1 s, so nothing weaker is felt however long it lasts) over the
// displacement the actuator gives at max_drive, at the frequency in its band where that ratio is
// smallest (where it is felt best: an LRA near its resonance). Below it a drive only keeps the
// actuator running; a platform without amplitude control plays it at full strength.
// e.g. lra-175 (12 um at 175 Hz, max_drive 0.7) at 2.9 cm2: 0.14 um / 8.4 um = 0.017 (-35.5 dB).
// Any thread (pure function).
#pragma once

#include "tactus/actuator/profile.hpp"

namespace tactus {

double felt_floor(const ActuatorProfile& actuator, double contact_area_cm2);

}  // namespace tactus
