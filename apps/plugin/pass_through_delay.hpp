// The music passed through, delayed by the engine's latency so it lines up with the vibration
// (docs/architecture.md, "The pipeline"). prepare() allocates; process() is real-time safe and
// takes the delay per block (it changes when a structural change moves the limiter's look-ahead).
#pragma once

#include <algorithm>
#include <vector>

namespace tactus::plugin {

class PassThroughDelay {
  public:
    // Room for delays up to max_delay_samples.
    void prepare(int channels, int max_delay_samples) {
        size_ = 1;
        while (size_ <= max_delay_samples) size_ *= 2;
        lines_.assign(static_cast<size_t>(channels),
                      std::vector<float>(static_cast<size_t>(size_)));
        write_ = 0;
    }
    void reset() noexcept {
        for (auto& line : lines_) std::fill(line.begin(), line.end(), 0.0f);
        write_ = 0;
    }
    int max_delay_samples() const noexcept { return size_ - 1; }

    // in and out: one pointer per channel; they may alias.
    void process(const float* const* in, float* const* out, int count, int delay_samples) noexcept {
        const int delay = std::clamp(delay_samples, 0, size_ - 1);
        const int mask = size_ - 1;
        for (size_t c = 0; c < lines_.size(); ++c) {
            float* line = lines_[c].data();
            int w = write_;
            for (int i = 0; i < count; ++i, w = (w + 1) & mask) {
                line[w] = in[c][i];
                out[c][i] = line[(w - delay) & mask];
            }
        }
        write_ = (write_ + count) & mask;
    }

  private:
    std::vector<std::vector<float>> lines_;
    int size_ = 1, write_ = 0;
};

}  // namespace tactus::plugin
