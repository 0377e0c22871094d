#include "sound_delay.hpp"

#include <algorithm>

namespace tactus::live {

SoundDelay::SoundDelay(int channels, int max_delay_samples, int delay_samples, int fade_samples)
    : rings_(static_cast<size_t>(std::max(channels, 0)),
             std::vector<float>(static_cast<size_t>(std::max(max_delay_samples, 0) + 1))),
      size_(std::max(max_delay_samples, 0) + 1),
      fade_samples_(std::max(fade_samples, 1)) {
    delay_ = next_delay_ = std::clamp(delay_samples, 0, size_ - 1);
    target_.store(delay_, std::memory_order_relaxed);
}

void SoundDelay::set_delay_samples(int delay_samples) noexcept {
    target_.store(std::clamp(delay_samples, 0, size_ - 1), std::memory_order_relaxed);
}

void SoundDelay::process(float* const* channels, int count) noexcept {
    if (!fading_) {
        const int target = target_.load(std::memory_order_relaxed);
        if (target != delay_) {
            next_delay_ = target;
            fade_done_ = 0;
            fading_ = true;
        }
    }
    const int size = size_;
    const auto behind = [size](int at, int delay) {
        return at >= delay ? at - delay : at - delay + size;
    };
    for (size_t c = 0; c < rings_.size(); ++c) {
        float* x = channels[c];
        float* ring = rings_[c].data();
        int at = write_, from = behind(write_, delay_), to = behind(write_, next_delay_);
        for (int i = 0; i < count; ++i) {
            ring[at] = x[i];  // written first: a delay of 0 reads it back
            if (fading_ && fade_done_ + i + 1 >= fade_samples_) {
                x[i] = ring[to];  // the fade is done
            } else if (fading_) {
                const float g =
                    static_cast<float>(fade_done_ + i + 1) / static_cast<float>(fade_samples_);
                x[i] = ring[from] + g * (ring[to] - ring[from]);
            } else {
                x[i] = ring[from];
            }
            if (++at == size) at = 0;
            if (++from == size) from = 0;
            if (++to == size) to = 0;
        }
    }
    write_ = (write_ + count) % size;
    if (fading_) {
        fade_done_ += count;
        if (fade_done_ >= fade_samples_) {
            delay_ = next_delay_;
            fading_ = false;
        }
    }
}

}  // namespace tactus::live
