#include "tactus/engine/channel_power.hpp"

#include <algorithm>

#include "tactus/dsp/sanitize.hpp"

namespace tactus {

void ChannelPower::prepare(const ProcessSpec& spec) {
    channels_.assign(static_cast<size_t>(spec.channels), {});
    for (auto& k : channels_) k.prepare(spec);
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
    float* const first = clean_.data();
    float* const second = first + clean_.size() / 2;
    size_t c = 0;
    for (; c + 1 < n; c += 2) {
        clean(c, first);
        clean(c + 1, second);
        KWeighting::add_power(channels_[c], first, channels_[c + 1], second, power, count);
    }
    if (c < n) {
        clean(c, first);
        channels_[c].add_power(first, power, count);
    }
}

}  // namespace tactus
