// The plugin's control thread: it runs `work` (taking the host's parameter changes to
// Engine::set), so the audio thread never waits, wakes or signals anyone.
//
// When it runs. The audio thread's setters only store atomics (no system call), so they cannot
// wake this thread: it polls. Polling every millisecond would wake every instance 1000 times a
// second with nothing to do; so it polls every kIdlePoll while idle, and every kBusyPoll for
// kBusyFor after `work` last found a change (automation comes in runs: a gesture or a ramp moves
// a parameter block after block, and each step then reaches the engine at once). Setters that
// are never on the audio thread (a restored state) call wake(): taken at once, not polled for.
//
// Bound: a change made on the audio thread reaches Engine::set within kIdlePoll (the first of a
// run) or kBusyPoll (the next ones), plus scheduling; the engine takes it at its next block.
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace tactus::plugin {

class ControlThread {
  public:
    static constexpr std::chrono::milliseconds kIdlePoll{20};
    static constexpr std::chrono::milliseconds kBusyPoll{1};
    static constexpr std::chrono::milliseconds kBusyFor{500};

    // `work` takes whatever changed and says whether anything had.
    explicit ControlThread(std::function<bool()> work) : work_(std::move(work)) {
        thread_ = std::thread([this] { loop(); });
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

    // Never the audio thread (it locks and signals): runs `work` now rather than at the poll.
    void wake() {
        {
            const std::lock_guard lock(mutex_);
            woken_ = true;
        }
        cv_.notify_one();
    }

  private:
    void loop() {
        using Clock = std::chrono::steady_clock;
        Clock::time_point last_change = Clock::now() - kBusyFor;
        std::unique_lock lock(mutex_);
        while (!stop_) {
            const auto poll = Clock::now() - last_change < kBusyFor ? kBusyPoll : kIdlePoll;
            cv_.wait_for(lock, poll, [this] { return stop_ || woken_; });
            if (stop_) break;
            woken_ = false;
            lock.unlock();
            if (work_()) last_change = Clock::now();
            lock.lock();
        }
    }

    std::function<bool()> work_;
    std::mutex mutex_;
    std::condition_variable cv_;
    bool stop_ = false;
    bool woken_ = false;
    std::thread thread_;
};

}  // namespace tactus::plugin
