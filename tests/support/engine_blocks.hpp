// Runs audio through an Engine block by block, as a host does. The engine is prepared (and given
// its settings, actuator and observer) by the caller, who keeps it for checks afterwards
// (clipped_samples(), reset(), the observer's counts); these functions only split the input.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "tactus/engine/engine.hpp"

namespace tactus::test {

// Processes n samples of `in` into `out` in blocks whose sizes cycle through `blocks` (the last
// block is cut short at the end). `in` and `out` may be the same buffer (in-place processing).
inline void process_in_blocks(Engine& engine, const float* in, float* out, size_t n,
                              const std::vector<int>& blocks) {
    size_t done = 0;
    for (size_t b = 0; done < n; ++b) {
        const int count = static_cast<int>(
            std::min<size_t>(n - done, static_cast<size_t>(blocks[b % blocks.size()])));
        engine.process(in + done, out + done, count);
        done += static_cast<size_t>(count);
    }
}

// The output for `in`, in blocks whose sizes cycle through `blocks`.
inline std::vector<float> process_in_blocks(Engine& engine, const std::vector<float>& in,
                                            const std::vector<int>& blocks) {
    std::vector<float> out(in.size());
    process_in_blocks(engine, in.data(), out.data(), in.size(), blocks);
    return out;
}

// The output for `in`, in blocks of `block` samples.
inline std::vector<float> process_in_blocks(Engine& engine, const std::vector<float>& in,
                                            int block) {
    return process_in_blocks(engine, in, std::vector<int>{block});
}

}  // namespace tactus::test
