#include "tactus/engine/channel_power.hpp"

#include <algorithm>

#include "tactus/dsp/sanitize.hpp"

namespace tactus {

void ChannelPower::prepare(const ProcessSpec& spec) {
    channels_.assign(static_cast<size_t>(spec.channels), {});
    for (auto& k : channels_) k.prepare(spec);
    max_block_ = spec.max_block;
    clean_.assign(2 * static_cast<size_t>(spec.max_block), 0.0f);
}

void ChannelPower::reset() noexcept {
    for (auto& k : channels_) k.reset();
}

// Channel by channel, two at a time (KWeighting's pair in one wavefront).
void ChannelPower::process(const float* const* in, int offset, int count, float* power) noexcept {
    std::fill(power, power + count, 0.0f);
    const size_t n = channels_.size();
    const auto clean = [&](size_t c, float* to) {
        const float* x = in[c] + offset;
        for (int i = 0; i < count; ++i) to[i] = sanitized(x[i]);
    };
    size_t c = 0;
    for (; c + 1 < n; c += 2) {
        clean(c, clean_.data());
        clean(c + 1, clean_.data() + max_block_);
        KWeighting::add_power(channels_[c], clean_.data(), channels_[c + 1],
                              clean_.data() + max_block_, power, count);
    }
    if (c < n) {
        clean(c, clean_.data());
        channels_[c].add_power(clean_.data(), power, count);
    }
}

}  // namespace tactus
