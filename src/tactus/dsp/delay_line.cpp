#include "tactus/dsp/delay_line.hpp"

#include <algorithm>

namespace tactus {

void DelayLine::prepare(int channels, int max_delay_samples, int delay_samples, int fade_samples) {
    size_ = std::max(max_delay_samples, 0) + 1;
    rings_.assign(static_cast<size_t>(std::max(channels, 0)),
                  std::vector<float>(static_cast<size_t>(size_)));
    fade_samples_ = std::max(fade_samples, 1);
    target_ = std::clamp(delay_samples, 0, size_ - 1);
    reset();
}

void DelayLine::reset() noexcept {
    for (auto& ring : rings_) std::fill(ring.begin(), ring.end(), 0.0f);
    write_ = 0;
    delay_ = next_delay_ = target_;
    fade_done_ = 0;
    fading_ = false;
}

void DelayLine::set_delay_samples(int delay_samples) noexcept {
    target_ = std::clamp(delay_samples, 0, size_ - 1);
}

void DelayLine::process(const float* const* in, float* const* out, int count) noexcept {
    if (!fading_ && target_ != delay_) {
        if (fade_samples_ <= 1) {
            delay_ = next_delay_ = target_;
        } else {
            next_delay_ = target_;
            fade_done_ = 0;
            fading_ = true;
        }
    }
    const int size = size_;
    const auto behind = [size](int at, int delay) {
        return at >= delay ? at - delay : at - delay + size;
    };
    for (size_t c = 0; c < rings_.size(); ++c) {
        const float* x = in[c];
        float* y = out[c];
        float* ring = rings_[c].data();
        int at = write_, from = behind(write_, delay_), to = behind(write_, next_delay_);
        for (int i = 0; i < count; ++i) {
            ring[at] = x[i];  // written first: a delay of 0 reads it back
            if (!fading_ || fade_done_ + i + 1 >= fade_samples_) {
                y[i] = ring[fading_ ? to : from];  // no crossfade, or the crossfade is done
            } else {
                const float g =
                    static_cast<float>(fade_done_ + i + 1) / static_cast<float>(fade_samples_);
                y[i] = ring[from] + g * (ring[to] - ring[from]);
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

}  // namespace tactus
