#include "sweep_recorder.hpp"

#include <algorithm>

namespace tactus::live {

SweepRecorder::SweepRecorder(std::vector<float> sweep, int output_channels, int output_channel,
                             int tail_frames)
    : sweep_(std::move(sweep)),
      recorded_(sweep_.size() + static_cast<size_t>(tail_frames)),
      output_channels_(output_channels),
      output_channel_(output_channel) {}

void SweepRecorder::process(const float* in, float* out, int frames) noexcept {
    std::fill(out, out + static_cast<ptrdiff_t>(output_channels_) * frames, 0.0f);
    if (!begun_.load(std::memory_order_acquire) || done_.load(std::memory_order_relaxed)) return;
    const auto n = std::min(static_cast<size_t>(frames), recorded_.size() - at_);
    float* to = out + static_cast<ptrdiff_t>(output_channel_) * frames;
    for (size_t i = 0; i < n; ++i) {
        to[i] = at_ + i < sweep_.size() ? sweep_[at_ + i] : 0.0f;
        recorded_[at_ + i] = in ? in[i] : 0.0f;
    }
    at_ += n;
    if (at_ == recorded_.size()) done_.store(true, std::memory_order_release);
}

}  // namespace tactus::live
