#include "meter_worker.hpp"

#include <stdexcept>
#include <utility>

namespace tactus::cli {
namespace {

using perception::Channel;
constexpr perception::SensationMeter::Channels kDriveChannels = {true, false, true, false};
constexpr perception::SensationMeter::Channels kSlowChannels = {false, true, false, true};

}  // namespace

MeterWorker::MeterWorker(double sample_rate_hz, const ActuatorProfile& actuator,
                         double contact_area_cm2, DriveMeter::OnReading on_reading)
    : on_reading_(std::move(on_reading)),
      displacement_stage_(
          [this, sample_rate_hz, actuator, contact_area_cm2] {
              slow_meter_.prepare(sample_rate_hz, DriveMeter::calibration(actuator),
                                  contact_area_cm2, kSlowChannels);
          },
          [this](const float* displacement, int count) {
              slow_meter_.write(displacement, count, keep_slow_);
          },
          [this] { slow_meter_.finish(keep_slow_); }),
      drive_stage_(
          [this, sample_rate_hz, actuator, contact_area_cm2] {
              drive_meter_.prepare(sample_rate_hz, actuator, contact_area_cm2, kDriveChannels);
          },
          [this](const float* drive, int count) {
              drive_meter_.write(drive, count, keep_drive_,
                                 [this](const float* displacement, int n) {
                                     displacement_stage_.write(displacement, n);
                                 });
          },
          [this] { drive_meter_.finish(keep_drive_); }) {}

void MeterWorker::finish() {
    drive_stage_.finish();         // every drive block modelled, its displacement handed on
    displacement_stage_.finish();  // and metered
    if (drive_readings_.size() != slow_readings_.size())
        throw std::logic_error("the meter's stages gave different numbers of readings");
    for (size_t i = 0; i < drive_readings_.size(); ++i) {
        perception::MeterReading r = drive_readings_[i];
        for (const Channel c : {Channel::NPI, Channel::NPIII})
            r.level_db[static_cast<size_t>(c)] = slow_readings_[i].level_db[static_cast<size_t>(c)];
        r.combined_db = perception::combined_sensation_db(r.level_db);
        on_reading_(r);
    }
}

}  // namespace tactus::cli
