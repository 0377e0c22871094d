// The longest latency an engine can report at a sample rate: the limiter's longest look-ahead
// the parameter table allows (post.lookahead_ms is structural: it can change while the engine
// runs, without a new prepare), plus the upsampler's few samples. What a front end's
// pass-through delay (DelayLine) is sized for, so the music follows the vibration.
#pragma once

#include "tactus/core/units.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

// Any thread.
inline int max_latency_samples(double sample_rate_hz) {
    constexpr int kUpsamplerMarginSamples = 256;
    return static_cast<int>(ms_to_samples(spec(P::post_lookahead_ms).max, sample_rate_hz)) +
           kUpsamplerMarginSamples;
}

}  // namespace tactus
