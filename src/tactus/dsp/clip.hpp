// The hard clip at the output ceiling: the absolute bound on what reaches the actuator. The
// limiter leaves a margin, so it should not act; it counts the samples it changed so that a
// run can say whether it did (PostChain, and Engine after the upsampler).
#pragma once

#include <cstdint>

namespace tactus {

// Clips samples to [-ceiling, ceiling] in place; returns how many it changed.
// Branch-free, so that the loop vectorises (a NaN passes, uncounted).
inline int64_t clip(float* samples, int count, float ceiling) noexcept {
    int clipped = 0;  // count <= INT_MAX
    for (int i = 0; i < count; ++i) {
        const float x = samples[i];
        clipped += (x > ceiling) | (x < -ceiling);
        samples[i] = x > ceiling ? ceiling : x < -ceiling ? -ceiling : x;
    }
    return clipped;
}

}  // namespace tactus
