#include "tactus/actuator/drive_meter.hpp"

#include <algorithm>

namespace tactus {

void DriveMeter::prepare(double sample_rate_hz, const ActuatorProfile& actuator,
                         double contact_area_cm2) {
    model_.prepare({.sample_rate_hz = sample_rate_hz, .max_block = kChunk}, actuator);
    // The model's output is in units of displacement_um at every frequency.
    const double um = actuator.displacement_um;
    meter_.prepare(
        sample_rate_hz, [um](double) { return um; }, contact_area_cm2);
    displacement_.assign(kChunk, 0.0f);
}

void DriveMeter::write(const float* drive, int count, const OnReading& on_reading) {
    for (int done = 0; done < count;) {
        const int n = std::min(kChunk, count - done);
        model_.process(drive + done, displacement_.data(), n);
        meter_.write(displacement_.data(), n, on_reading);
        done += n;
    }
}

}  // namespace tactus
