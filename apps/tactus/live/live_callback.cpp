#include "live_callback.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sync_delay.hpp"

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
    : engine_(engine), player_(player), routing_(std::move(routing)) {
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
        // Only the channels heard are delayed.
        const size_t heard = std::min(static_cast<size_t>(sources), routing_.sound_channels.size());
        sound_pointers_.resize(heard);
        if (sync_delay_samples != kNoSync) {
            const double rate_hz = engine.sample_rate_hz();
            delay_.prepare(static_cast<int>(heard), max_vibration_delay_samples(rate_hz),
                           sync_delay_samples,
                           static_cast<int>(Engine::kCrossfadeMs / 1000 * rate_hz));
            sync_ = true;
            sync_target_.store(delay_.delay_samples(), std::memory_order_relaxed);
        }
    }
    in_pointers_.resize(static_cast<size_t>(std::max(sources, 1)));
    out_pointers_.resize(routing_.actuator_channels.size());
}

LiveCallback::~LiveCallback() {
    // A device lost with its server may be left closing on a thread of its own (reconnector.hpp)
    // and never joined; its audio thread has ended, but nothing else orders its last process()
    // before this delete. The acquiring load does, as DeviceStream's does for the stream.
    (void)frames_.load(std::memory_order_acquire);
}

void LiveCallback::set_sync_delay_samples(int samples) noexcept {
    if (sync_)
        sync_target_.store(std::clamp(samples, 0, delay_.max_delay_samples()),
                           std::memory_order_relaxed);
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
    const double period_s = frames / engine_.sample_rate_hz();
    const double spent_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    raise(load_, spent_s / period_s);
    // Last: released to the destructor's acquiring load (see ~LiveCallback).
    frames_.fetch_add(frames, std::memory_order_release);
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
        const auto channel = [&](size_t s) {
            return out + static_cast<ptrdiff_t>(routing_.sound_channels[s]) * out_stride + offset;
        };
        const size_t heard = sound_pointers_.size();
        for (size_t s = 0; s < heard; ++s) sound_pointers_[s] = channel(s);
        if (sync_) {  // delayed straight into the device's channels
            delay_.set_delay_samples(sync_target_.load(std::memory_order_relaxed));
            delay_.process(played_pointers_.data(), sound_pointers_.data(), count);
        } else {
            for (size_t s = 0; s < heard; ++s) std::copy_n(played_[s].data(), count, channel(s));
        }
        for (size_t s = heard; s < routing_.sound_channels.size(); ++s)
            std::copy_n(channel(s % heard), count, channel(s));
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
