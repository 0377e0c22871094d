// The audio side of `tactus calibrate`: plays a sweep on one output channel while recording one
// input channel, into buffers made beforehand (the callback only copies). Done when the sweep
// and the tail after it have been recorded.
#pragma once

#include <atomic>
#include <vector>

#include "device_stream.hpp"

namespace tactus::live {

class SweepRecorder final : public AudioCallback {
  public:
    // `output_channel` of `output_channels`; records `sweep.size() + tail_frames` frames of the
    // first input channel.
    SweepRecorder(std::vector<float> sweep, int output_channels, int output_channel,
                  int tail_frames);
    void process(const float* in, float* out, int frames) noexcept override;
    void note_xrun() noexcept override { xruns_.fetch_add(1, std::memory_order_relaxed); }
    // Any thread: until called, silence and nothing recorded (the ports may not be connected).
    void begin() noexcept { begun_.store(true, std::memory_order_release); }
    bool done() const { return done_.load(std::memory_order_acquire); }
    long xruns() const { return xruns_.load(std::memory_order_relaxed); }
    // After done().
    const std::vector<float>& recorded() const { return recorded_; }
    const std::vector<float>& sweep() const { return sweep_; }

  private:
    std::vector<float> sweep_, recorded_;
    int output_channels_, output_channel_;
    size_t at_ = 0;
    std::atomic<bool> begun_{false}, done_{false};
    std::atomic<long> xruns_{0};
};

}  // namespace tactus::live
