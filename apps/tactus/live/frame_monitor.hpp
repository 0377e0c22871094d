// The engine's one frame reader in `tactus live`: a thread that takes every analysis frame off
// the engine's queue (Engine::pop_frame), counts onsets for the status line and sends features,
// onsets (each with its drum part, once decided) and the vibration program over OSC at their rate.
#pragma once

#include <atomic>
#include <optional>
#include <thread>

#include "osc_sender.hpp"

namespace tactus::live {

class FrameMonitor {
  public:
    // `engine` has its frame queue enabled; `sender` may be null.
    FrameMonitor(Engine& engine, OscSender* sender, double osc_rate_hz);
    ~FrameMonitor();
    FrameMonitor(const FrameMonitor&) = delete;
    FrameMonitor& operator=(const FrameMonitor&) = delete;

    // Any thread: onsets since the start.
    int64_t onsets() const { return onsets_.load(std::memory_order_relaxed); }

  private:
    void run();
    Engine& engine_;
    OscSender* sender_;
    double osc_period_s_;
    std::atomic<int64_t> onsets_{0};
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace tactus::live
