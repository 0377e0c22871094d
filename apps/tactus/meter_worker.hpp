// A DriveMeter (actuator/drive_meter.hpp) on a thread of its own: a render hands it the drive
// block by block and goes on, so a metered render (`tactus report`, `tactus studio`) costs the
// longer of rendering and metering rather than their sum. Readings come, in order, on the
// worker's thread; once finish() has returned, every reading has come and the worker is gone.
#pragma once

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include "tactus/actuator/drive_meter.hpp"

namespace tactus::cli {

class MeterWorker {
  public:
    // Prepares the meter on the worker's thread and starts it.
    MeterWorker(double sample_rate_hz, const ActuatorProfile& actuator, double contact_area_cm2,
                DriveMeter::OnReading on_reading);
    // Stops the worker if finish() was not called (a render that failed): readings may be lost.
    ~MeterWorker();
    MeterWorker(const MeterWorker&) = delete;
    MeterWorker& operator=(const MeterWorker&) = delete;

    // The render's thread: a copy of `count` samples of drive is queued.
    void write(const float* drive, int count);
    // The render's thread: meters what is queued and the meter's tail, then joins the worker.
    void finish();

  private:
    // Handed over in blocks this long or more: fewer wake-ups of the worker.
    static constexpr size_t kHandOverSamples = 16384;
    void hand_over();
    void run(double sample_rate_hz, const ActuatorProfile& actuator, double contact_area_cm2);

    DriveMeter::OnReading on_reading_;
    std::vector<float> pending_;  // the render thread's, not yet handed over
    std::mutex mutex_;
    std::condition_variable queued_;
    std::deque<std::vector<float>> blocks_;
    bool finishing_ = false, abandoned_ = false;
    std::thread worker_;
};

}  // namespace tactus::cli
