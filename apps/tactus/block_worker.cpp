#include "block_worker.hpp"

#include <utility>

namespace tactus::cli {

BlockWorker::BlockWorker(std::function<void()> start, Take take, std::function<void()> done)
    : start_(std::move(start)),
      take_(std::move(take)),
      done_(std::move(done)),
      worker_([this] { run(); }) {
    pending_.reserve(2 * kHandOverSamples);
}

BlockWorker::~BlockWorker() {
    if (!worker_.joinable()) return;
    {
        const std::lock_guard lock(mutex_);
        abandoned_ = true;
    }
    queued_.notify_one();
    worker_.join();
}

void BlockWorker::write(const float* samples, int count) {
    pending_.insert(pending_.end(), samples, samples + count);
    if (pending_.size() >= kHandOverSamples) hand_over();
}

void BlockWorker::hand_over() {
    {
        const std::lock_guard lock(mutex_);
        blocks_.push_back(std::exchange(pending_, {}));
    }
    pending_.reserve(2 * kHandOverSamples);  // grown once, not copied at every doubling
    queued_.notify_one();
}

void BlockWorker::finish() {
    if (!pending_.empty()) hand_over();
    {
        const std::lock_guard lock(mutex_);
        finishing_ = true;
    }
    queued_.notify_one();
    worker_.join();
}

void BlockWorker::run() {
    start_();
    for (;;) {
        std::vector<float> block;
        {
            std::unique_lock lock(mutex_);
            queued_.wait(lock, [&] { return !blocks_.empty() || finishing_ || abandoned_; });
            if (abandoned_) return;
            if (blocks_.empty()) break;  // finishing, and everything taken
            block = std::move(blocks_.front());
            blocks_.pop_front();
        }
        take_(block.data(), static_cast<int>(block.size()));
    }
    done_();
}

}  // namespace tactus::cli
