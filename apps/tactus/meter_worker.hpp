// A DriveMeter (actuator/drive_meter.hpp) on threads of its own: a render hands it the drive
// block by block and goes on, so a metered render (`tactus report`, `tactus studio`) costs the
// longer of rendering and metering rather than their sum. The meter's work is split in two
// stages of about equal cost (their channels are independent): one models the actuator and
// meters P and NPII, and hands the displacement to the other, which meters NPI and NPIII (the
// long FFTs); with the render's, three threads share the machine's cores. The readings are
// bit for bit one DriveMeter's; they come, in order, on the render's thread inside finish().
#pragma once

#include <vector>

#include "block_worker.hpp"
#include "tactus/actuator/drive_meter.hpp"

namespace tactus::cli {

class MeterWorker {
  public:
    // Prepares the meters on the workers' threads and starts them.
    MeterWorker(double sample_rate_hz, const ActuatorProfile& actuator, double contact_area_cm2,
                DriveMeter::OnReading on_reading);

    // The render's thread: a copy of `count` samples of drive is queued.
    void write(const float* drive, int count) { drive_stage_.write(drive, count); }
    // The render's thread: meters what is queued and the meter's tail, joins the workers and
    // passes every reading to on_reading.
    void finish();

  private:
    DriveMeter::OnReading on_reading_;
    DriveMeter drive_meter_;                 // P and NPII: the drive stage's
    perception::SensationMeter slow_meter_;  // NPI and NPIII: the displacement stage's
    std::vector<perception::MeterReading> drive_readings_, slow_readings_;
    // Each stage's readings kept, in order, for finish().
    const DriveMeter::OnReading keep_drive_ = [this](const perception::MeterReading& r) {
        drive_readings_.push_back(r);
    };
    const DriveMeter::OnReading keep_slow_ = [this](const perception::MeterReading& r) {
        slow_readings_.push_back(r);
    };
    // Declared last, destroyed first (the drive stage feeds the displacement stage).
    BlockWorker displacement_stage_, drive_stage_;
};

}  // namespace tactus::cli
