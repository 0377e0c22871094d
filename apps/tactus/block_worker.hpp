// A thread that takes blocks of samples, in order, from the thread that feeds it: the feeder
// writes and goes on. The metered renders' meter (meter_worker.hpp) runs on one. Samples are
// handed over in blocks of kHandOverSamples or more (fewer wake-ups). Not real-time: write()
// allocates.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace tactus::cli {

class BlockWorker {
  public:
    using Take = std::function<void(const float* samples, int count)>;

    // The worker's thread calls `start`, then `take` for every block, in order, then `done`
    // once finish() was called and every block is taken.
    BlockWorker(std::function<void()> start, Take take, std::function<void()> done);
    // Stops the worker if finish() was not called (a render that failed): blocks may be lost.
    ~BlockWorker();
    BlockWorker(const BlockWorker&) = delete;
    BlockWorker& operator=(const BlockWorker&) = delete;

    // The feeding thread (one): a copy of `count` samples is queued.
    void write(const float* samples, int count);
    // The feeding thread: hands over what is queued, then joins the worker (`done` has run).
    void finish();

  private:
    static constexpr size_t kHandOverSamples = 16384;
    void hand_over();
    void run();

    std::function<void()> start_;
    Take take_;
    std::function<void()> done_;
    std::vector<float> pending_;  // the feeder's, not yet handed over
    std::mutex mutex_;
    std::condition_variable queued_;
    std::deque<std::vector<float>> blocks_;
    bool finishing_ = false, abandoned_ = false;
    std::thread worker_;
};

}  // namespace tactus::cli
