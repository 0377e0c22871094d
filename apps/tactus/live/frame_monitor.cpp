#include "frame_monitor.hpp"

#include <chrono>

namespace tactus::live {
namespace {

constexpr auto kPoll = std::chrono::milliseconds(2);  // well under an analysis hop

}  // namespace

FrameMonitor::FrameMonitor(Engine& engine, OscSender* sender, double osc_rate_hz)
    : engine_(engine), sender_(sender), osc_period_s_(1.0 / osc_rate_hz) {
    thread_ = std::thread([this] { run(); });
}

FrameMonitor::~FrameMonitor() {
    stop_ = true;
    thread_.join();
}

void FrameMonitor::run() {
    using Clock = std::chrono::steady_clock;
    auto next_send = Clock::now();
    AnalysisFrame frame, latest;
    bool fresh = false;
    OnsetDecisions decisions;  // an onset is sent once its part is decided
    const auto send_onset = [this](const DecidedOnset& onset) { sender_->send_onset(onset); };
    while (!stop_) {
        while (engine_.pop_frame(frame)) {
            latest = frame;
            fresh = true;
            if (frame.features.onset) onsets_.fetch_add(1, std::memory_order_relaxed);
            if (sender_) decisions.add(frame.features, send_onset);
        }
        if (sender_ && fresh && Clock::now() >= next_send) {
            sender_->send_state(latest);
            fresh = false;
            next_send += std::chrono::duration_cast<Clock::duration>(
                std::chrono::duration<double>(osc_period_s_));
            if (next_send < Clock::now()) next_send = Clock::now();
        }
        std::this_thread::sleep_for(kPoll);
    }
}

}  // namespace tactus::live
