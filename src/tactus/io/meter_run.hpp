// The sensation-level meter over a whole vibration (a file, or one in memory): the actuators'
// mean through DriveMeter block by block, then its last readings. `tactus meter` and the Python
// module's meter() are this one loop.
#pragma once

#include "tactus/actuator/drive_meter.hpp"
#include "tactus/io/run_file.hpp"

namespace tactus {

// Meters `vibration` driving `actuator` at `contact_area_cm2`, calling on_reading every reading
// (the last ones, past the end, included).
RunSummary meter_source(AudioSource& vibration, const ActuatorProfile& actuator,
                        double contact_area_cm2, const DriveMeter::OnReading& on_reading,
                        const RunCallbacks& callbacks = {});

}  // namespace tactus
