// Several channels to one: their mean, sample by sample (the engine's default downmix; the
// analysis reads one signal).
#pragma once

#include <algorithm>

namespace tactus {

// out[i] = mean over c of in[c][offset + i]; out may not alias the inputs.
inline void downmix_mean(const float* const* in, int channels, int offset, float* out,
                         int count) noexcept {
    if (channels == 2) {  // the common case, in a loop that vectorises
        for (int i = 0; i < count; ++i) out[i] = (in[0][offset + i] + in[1][offset + i]) * 0.5f;
        return;
    }
    std::copy_n(in[0] + offset, count, out);
    for (int c = 1; c < channels; ++c)
        for (int i = 0; i < count; ++i) out[i] += in[c][offset + i];
    const float scale = 1.0f / static_cast<float>(channels);
    if (channels > 1)
        for (int i = 0; i < count; ++i) out[i] *= scale;
}

}  // namespace tactus
