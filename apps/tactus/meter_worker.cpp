#include "meter_worker.hpp"

#include <utility>

namespace tactus::cli {

MeterWorker::MeterWorker(double sample_rate_hz, const ActuatorProfile& actuator,
                         double contact_area_cm2, DriveMeter::OnReading on_reading)
    : on_reading_(std::move(on_reading)),
      worker_([this, sample_rate_hz, actuator, contact_area_cm2] {
          run(sample_rate_hz, actuator, contact_area_cm2);
      }) {}

MeterWorker::~MeterWorker() {
    if (!worker_.joinable()) return;
    {
        const std::lock_guard lock(mutex_);
        abandoned_ = true;
    }
    queued_.notify_one();
    worker_.join();
}

void MeterWorker::write(const float* drive, int count) {
    pending_.insert(pending_.end(), drive, drive + count);
    if (pending_.size() >= kHandOverSamples) hand_over();
}

void MeterWorker::hand_over() {
    {
        const std::lock_guard lock(mutex_);
        blocks_.push_back(std::exchange(pending_, {}));
    }
    queued_.notify_one();
}

void MeterWorker::finish() {
    if (!pending_.empty()) hand_over();
    {
        const std::lock_guard lock(mutex_);
        finishing_ = true;
    }
    queued_.notify_one();
    worker_.join();
}

void MeterWorker::run(double sample_rate_hz, const ActuatorProfile& actuator,
                      double contact_area_cm2) {
    DriveMeter meter;
    meter.prepare(sample_rate_hz, actuator, contact_area_cm2);
    for (;;) {
        std::vector<float> block;
        {
            std::unique_lock lock(mutex_);
            queued_.wait(lock, [&] { return !blocks_.empty() || finishing_ || abandoned_; });
            if (abandoned_) return;
            if (blocks_.empty()) break;  // finishing, and everything metered
            block = std::move(blocks_.front());
            blocks_.pop_front();
        }
        meter.write(block.data(), static_cast<int>(block.size()), on_reading_);
    }
    meter.finish(on_reading_);
}

}  // namespace tactus::cli
