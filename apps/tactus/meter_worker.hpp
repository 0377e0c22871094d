// A DriveMeter (actuator/drive_meter.hpp) on a thread of its own: a render hands it the drive
// block by block and goes on, so a metered render (`tactus report`, `tactus studio`) costs the
// longer of rendering and metering rather than their sum. The readings are bit for bit one
// DriveMeter's; they come, in order, on the render's thread inside finish().
#pragma once

#include <vector>

#include "block_worker.hpp"
#include "tactus/actuator/drive_meter.hpp"

namespace tactus::cli {

class MeterWorker {
  public:
    // Prepares the meter on the worker's thread and starts it.
    MeterWorker(double sample_rate_hz, const ActuatorProfile& actuator, double contact_area_cm2,
                DriveMeter::OnReading on_reading);

    // The render's thread: a copy of `count` samples of drive is queued.
    void write(const float* drive, int count) { worker_.write(drive, count); }
    // The render's thread: meters what is queued and the meter's tail, joins the worker and
    // passes every reading to on_reading.
    void finish();

  private:
    DriveMeter::OnReading on_reading_;
    DriveMeter meter_;  // the worker's
    std::vector<perception::MeterReading> readings_;
    const DriveMeter::OnReading keep_ = [this](const perception::MeterReading& r) {
        readings_.push_back(r);
    };
    BlockWorker worker_;  // declared last, destroyed first: it uses the members above
};

}  // namespace tactus::cli
