// The hard clip at the output ceiling: the absolute bound on what reaches the actuator. The
// limiter leaves a margin, so it should not act; it counts the samples it changed so that a
// run can say whether it did (PostChain, and Engine after the upsampler).
#pragma once

#include <cstdint>

namespace tactus {

// Clips samples to [-ceiling, ceiling] in place; returns how many it changed.
inline int64_t clip(float* samples, int count, float ceiling) noexcept {
    int64_t clipped = 0;
    for (int i = 0; i < count; ++i) {
        if (samples[i] > ceiling)
            samples[i] = ceiling, ++clipped;
        else if (samples[i] < -ceiling)
            samples[i] = -ceiling, ++clipped;
    }
    return clipped;
}

}  // namespace tactus
