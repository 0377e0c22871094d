#include "tactus/engine/engine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "tactus/engine/denormals.hpp"

namespace tactus {

void Engine::prepare(double sample_rate_hz, int max_block) {
    if (!(sample_rate_hz >= kMinSampleRateHz && sample_rate_hz <= kMaxSampleRateHz))
        throw std::invalid_argument(
            fmt::format("sample rate {} Hz is outside the supported {}-{} Hz", sample_rate_hz,
                        kMinSampleRateHz, kMaxSampleRateHz));
    if (max_block < 1 || max_block > kMaxBlock)
        throw std::invalid_argument(
            fmt::format("block size {} is outside the supported 1-{}", max_block, kMaxBlock));
    sample_rate_hz_ = sample_rate_hz;
    analyzer_.prepare(sample_rate_hz, settings_);
    mapper_.prepare(settings_, sample_rate_hz / analyzer_.hop_samples());
    voice_.prepare(sample_rate_hz, settings_[P::post_band_high_hz]);
    post_.prepare(sample_rate_hz, settings_, actuator_ ? &*actuator_ : nullptr);
    reset();
}

void Engine::reset() noexcept {
    analyzer_.reset();
    mapper_.reset();
    voice_.reset();
    post_.reset();
}

void Engine::process(const float* in, float* out, int count) noexcept {
    const ScopedFlushDenormals no_denormals;
    int done = 0;  // `in` is read before `out` is written, chunk by chunk: they may alias
    while (done < count) {
        const int chunk = std::min(count - done, analyzer_.samples_to_next_frame());
        const bool frame_due = analyzer_.write(in + done, chunk);
        voice_.render(out + done, chunk);
        if (frame_due) {
            const Features& features = analyzer_.analyse();
            const ControlFrame control = mapper_.map(features);
            voice_.apply(control);
            if (observer_) observer_->on_frame(features, control);
        }
        done += chunk;
    }
    post_.process(out, count);
}

}  // namespace tactus
