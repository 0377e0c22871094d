// The sensation meter (perception/meter.hpp) of an actuator's drive: the drive goes through the
// profile's time-domain model (actuator_model.hpp: an LRA's resonance, an ERM's spin-up and
// speed-tied frequency) and its displacement is metered. What `tactus meter`, `tactus analyze`,
// `tactus report` and Python's tactus.meter() read, so they agree. Offline threads: prepare()
// allocates, write() does not.
#pragma once

#include <functional>
#include <vector>

#include "tactus/actuator/actuator_model.hpp"
#include "tactus/perception/meter.hpp"

namespace tactus {

class DriveMeter {
  public:
    using OnReading = std::function<void(const perception::MeterReading&)>;
    static constexpr int kChunk = 4096;  // samples modelled at a time

    void prepare(double sample_rate_hz, const ActuatorProfile& actuator, double contact_area_cm2);
    void write(const float* drive, int count, const OnReading& on_reading);
    void finish(const OnReading& on_reading) { meter_.finish(on_reading); }

  private:
    ActuatorModel model_;
    perception::SensationMeter meter_;
    std::vector<float> displacement_;
};

}  // namespace tactus
