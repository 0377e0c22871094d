#include "tactus/actuator/drive_meter.hpp"

#include <algorithm>

namespace tactus {

perception::SensationMeter::Calibration DriveMeter::calibration(const ActuatorProfile& actuator) {
    // The model's output is in units of displacement_um at every frequency.
    const double um = actuator.displacement_um;
    return [um](double) { return um; };
}

void DriveMeter::prepare(double sample_rate_hz, const ActuatorProfile& actuator,
                         double contact_area_cm2,
                         const perception::SensationMeter::Channels& channels) {
    model_.prepare({.sample_rate_hz = sample_rate_hz, .max_block = kChunk}, actuator);
    meter_.prepare(sample_rate_hz, calibration(actuator), contact_area_cm2, channels);
    displacement_.assign(kChunk, 0.0f);
}

void DriveMeter::write(const float* drive, int count, const OnReading& on_reading,
                       const OnDisplacement& on_displacement) {
    for (int done = 0; done < count;) {
        const int n = std::min(kChunk, count - done);
        model_.process(drive + done, displacement_.data(), n);
        if (on_displacement) on_displacement(displacement_.data(), n);
        meter_.write(displacement_.data(), n, on_reading);
        done += n;
    }
}

}  // namespace tactus
