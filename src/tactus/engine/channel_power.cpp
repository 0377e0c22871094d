#include "tactus/engine/channel_power.hpp"

#include <algorithm>

#include "tactus/dsp/sanitize.hpp"

namespace tactus {

void ChannelPower::prepare(const ProcessSpec& spec) {
    channels_.assign(static_cast<size_t>(spec.channels), {});
    for (auto& k : channels_) k.prepare(spec);
    clean_.assign(static_cast<size_t>(spec.max_block), 0.0f);
}

void ChannelPower::reset() noexcept {
    for (auto& k : channels_) k.reset();
}

void ChannelPower::process(const float* const* in, int offset, int count, float* power) noexcept {
    std::fill(power, power + count, 0.0f);
    for (size_t c = 0; c < channels_.size(); ++c) {
        const float* x = in[c] + offset;
        for (int i = 0; i < count; ++i) clean_[i] = sanitized(x[i]);
        channels_[c].add_power(clean_.data(), power, count);
    }
}

}  // namespace tactus
