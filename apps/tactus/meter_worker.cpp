#include "meter_worker.hpp"

#include <utility>

namespace tactus::cli {

MeterWorker::MeterWorker(double sample_rate_hz, const ActuatorProfile& actuator,
                         double contact_area_cm2, DriveMeter::OnReading on_reading)
    : on_reading_(std::move(on_reading)),
      worker_([this, sample_rate_hz, actuator,
               contact_area_cm2] { meter_.prepare(sample_rate_hz, actuator, contact_area_cm2); },
              [this](const float* drive, int count) { meter_.write(drive, count, keep_); },
              [this] { meter_.finish(keep_); }) {}

void MeterWorker::finish() {
    worker_.finish();  // every drive block metered, the tail too
    for (const perception::MeterReading& r : readings_) on_reading_(r);
}

}  // namespace tactus::cli
