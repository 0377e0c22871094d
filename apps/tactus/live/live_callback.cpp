#include "live_callback.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tactus::live {
namespace {

// Raises `meter` to `value` (one writer, readers that reset it).
template <typename T>
void raise(std::atomic<T>& meter, T value) noexcept {
    T seen = meter.load(std::memory_order_relaxed);
    while (value > seen && !meter.compare_exchange_weak(seen, value, std::memory_order_relaxed)) {
    }
}

float peak(const float* x, int count) noexcept {
    float p = 0;
    for (int i = 0; i < count; ++i) p = std::max(p, std::abs(x[i]));
    return p;
}

}  // namespace

LiveCallback::LiveCallback(Engine& engine, Player* player, Routing routing, int sync_delay_samples)
    : engine_(engine),
      player_(player),
      routing_(std::move(routing)),
      sync_delay_(std::max(0, sync_delay_samples)) {
    if (static_cast<int>(routing_.actuator_channels.size()) != engine.actuators())
        throw std::invalid_argument("live: one device channel per actuator output");
    const auto check = [&](int channel) {
        if (channel < 0 || channel >= routing_.device_outputs)
            throw std::invalid_argument("live: an output channel beyond the device's");
    };
    for (int c : routing_.actuator_channels) check(c);
    for (int c : routing_.sound_channels) check(c);
    const int sources = player_ ? player_->channels() : routing_.device_inputs;
    if (player_) {
        played_.assign(static_cast<size_t>(sources), std::vector<float>(kChunk));
        for (auto& p : played_) played_pointers_.push_back(p.data());
        if (sync_delay_ > 0)
            delay_.assign(static_cast<size_t>(sources),
                          std::vector<float>(static_cast<size_t>(sync_delay_)));
    }
    in_pointers_.resize(static_cast<size_t>(std::max(sources, 1)));
    out_pointers_.resize(routing_.actuator_channels.size());
}

void LiveCallback::process(const float* in, float* out, int frames) noexcept {
    const auto start = std::chrono::steady_clock::now();
    for (int c = 0; c < routing_.device_outputs; ++c)  // channels nothing drives stay silent
        std::fill(out + static_cast<ptrdiff_t>(c) * frames,
                  out + static_cast<ptrdiff_t>(c + 1) * frames, 0.0f);
    if (!begun_.load(std::memory_order_acquire)) return;
    for (int done = 0; done < frames;) {
        const int count = std::min(kChunk, frames - done);
        process_chunk(in, frames, out, frames, done, count);
        done += count;
    }
    frames_.fetch_add(frames, std::memory_order_relaxed);
    const double period_s = frames / engine_.sample_rate_hz();
    const double spent_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    raise(load_, spent_s / period_s);
}

void LiveCallback::process_chunk(const float* in, int in_stride, float* out, int out_stride,
                                 int offset, int count) noexcept {
    int sources = routing_.device_inputs;
    if (player_) {
        player_->read(played_pointers_.data(), count);
        sources = player_->channels();
        for (int c = 0; c < sources; ++c)
            in_pointers_[static_cast<size_t>(c)] = played_[static_cast<size_t>(c)].data();
    } else {
        for (int c = 0; c < sources; ++c)
            in_pointers_[static_cast<size_t>(c)] =
                in + static_cast<ptrdiff_t>(c) * in_stride + offset;
    }
    float in_peak = 0;
    for (int c = 0; c < sources; ++c)
        in_peak = std::max(in_peak, peak(in_pointers_[static_cast<size_t>(c)], count));
    raise(input_peak_, in_peak);

    if (player_ && !routing_.sound_channels.empty()) {  // the sound, before the engine runs
        const int n_sound = static_cast<int>(routing_.sound_channels.size());
        for (int s = 0; s < n_sound; ++s) {
            const float* from = played_[static_cast<size_t>(s % sources)].data();
            float* to = out +
                        static_cast<ptrdiff_t>(routing_.sound_channels[static_cast<size_t>(s)]) *
                            out_stride +
                        offset;
            std::copy(from, from + count, to);
        }
        if (sync_delay_ > 0) {  // every sound channel reads its source through one ring
            int at = delay_at_;
            for (int s = 0; s < n_sound; ++s) {
                auto& ring = delay_[static_cast<size_t>(s % sources)];
                float* x = out +
                           static_cast<ptrdiff_t>(routing_.sound_channels[static_cast<size_t>(s)]) *
                               out_stride +
                           offset;
                at = delay_at_;
                if (s < sources) {  // the first channel reading a source turns its ring
                    for (int i = 0; i < count; ++i) {
                        const float delayed = ring[static_cast<size_t>(at)];
                        ring[static_cast<size_t>(at)] = x[i];
                        x[i] = delayed;
                        if (++at == sync_delay_) at = 0;
                    }
                } else {  // later ones copy what the first read
                    const float* first =
                        out +
                        static_cast<ptrdiff_t>(
                            routing_.sound_channels[static_cast<size_t>(s % sources)]) *
                            out_stride +
                        offset;
                    std::copy(first, first + count, x);
                }
            }
            delay_at_ = at;
        }
    }

    for (size_t a = 0; a < out_pointers_.size(); ++a)
        out_pointers_[a] =
            out + static_cast<ptrdiff_t>(routing_.actuator_channels[a]) * out_stride + offset;
    engine_.process(in_pointers_.data(), out_pointers_.data(), count);
    float out_peak = 0;
    for (float* o : out_pointers_) out_peak = std::max(out_peak, peak(o, count));
    raise(output_peak_, out_peak);
}

Meters LiveCallback::take_meters() noexcept {
    return {.input_peak = input_peak_.exchange(0, std::memory_order_relaxed),
            .output_peak = output_peak_.exchange(0, std::memory_order_relaxed),
            .load = load_.exchange(0, std::memory_order_relaxed),
            .xruns = xruns_.load(std::memory_order_relaxed),
            .frames = frames_.load(std::memory_order_relaxed)};
}

}  // namespace tactus::live
