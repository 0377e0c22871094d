// The sensation-level meter over a whole vibration (a file, or one in memory): the actuators'
// mean, or each output's channel through its own actuator, through DriveMeter block by block,
// then its last readings. `tactus meter` and the Python module's meter() are this one loop.
#pragma once

#include <functional>
#include <vector>

#include "tactus/actuator/drive_meter.hpp"
#include "tactus/io/run_file.hpp"

namespace tactus {

// One vibration metered: a channel of the file (-1: the channels' mean) driving an actuator.
struct MeteredChannel {
    int channel = -1;
    ActuatorProfile actuator;
};

// Meters each of `metered` at `contact_area_cm2` in one pass over `vibration`, calling
// on_reading(index in `metered`, reading) every reading (the last ones, past the end, included).
RunSummary meter_source(
    AudioSource& vibration, const std::vector<MeteredChannel>& metered, double contact_area_cm2,
    const std::function<void(size_t, const perception::MeterReading&)>& on_reading,
    const RunCallbacks& callbacks = {});

// The channels' mean driving `actuator`.
inline RunSummary meter_source(AudioSource& vibration, const ActuatorProfile& actuator,
                               double contact_area_cm2, const DriveMeter::OnReading& on_reading,
                               const RunCallbacks& callbacks = {}) {
    return meter_source(
        vibration, {{.channel = -1, .actuator = actuator}}, contact_area_cm2,
        [&](size_t, const perception::MeterReading& r) { on_reading(r); }, callbacks);
}

}  // namespace tactus
