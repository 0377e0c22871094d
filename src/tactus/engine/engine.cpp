#include "tactus/engine/engine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "tactus/engine/denormals.hpp"
#include "tactus/synthesis/components.hpp"

namespace tactus {

void Engine::set_actuator(std::optional<ActuatorProfile> actuator) {
    if (actuator) settings_.set(P::actuator_dc, actuator->dc ? 1.0 : 0.0);
    actuator_ = std::move(actuator);
}

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
    flutter_.assign(flutter_enabled(settings_) ? static_cast<size_t>(max_block) : 0, 0.0f);
    pressure_.assign(pressure_enabled(settings_) ? static_cast<size_t>(max_block) : 0, 0.0f);
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
    float* const flutter = flutter_.empty() ? nullptr : flutter_.data();
    float* const pressure = pressure_.empty() ? nullptr : pressure_.data();
    while (done < count) {
        const int chunk = std::min(count - done, analyzer_.samples_to_next_frame());
        const bool frame_due = analyzer_.write(in + done, chunk);
        voice_.render(out + done, flutter ? flutter + done : nullptr,
                      pressure ? pressure + done : nullptr, chunk);
        if (frame_due) {
            const Features& features = analyzer_.analyse();
            const ControlFrame control = mapper_.map(features);
            voice_.apply(control);
            if (observer_) observer_->on_frame(features, control);
        }
        done += chunk;
    }
    post_.process(out, flutter, pressure, count);
}

}  // namespace tactus
