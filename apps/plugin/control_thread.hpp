// The plugin's control thread: every kPollMs it runs `work` (taking the host's parameter
// changes to Engine::set), so the audio thread never waits, wakes or signals anyone. A change
// reaches the engine within kPollMs plus the engine's next block.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace tactus::plugin {

class ControlThread {
  public:
    static constexpr int kPollMs = 1;

    explicit ControlThread(std::function<void()> work) : work_(std::move(work)) {
        thread_ = std::thread([this] {
            std::unique_lock lock(mutex_);
            while (
                !cv_.wait_for(lock, std::chrono::milliseconds(kPollMs), [this] { return stop_; })) {
                lock.unlock();
                work_();
                lock.lock();
            }
        });
    }
    ~ControlThread() {
        {
            const std::lock_guard lock(mutex_);
            stop_ = true;
        }
        cv_.notify_one();
        thread_.join();
    }
    ControlThread(const ControlThread&) = delete;
    ControlThread& operator=(const ControlThread&) = delete;

  private:
    std::function<void()> work_;
    std::mutex mutex_;
    std::condition_variable cv_;
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace tactus::plugin
