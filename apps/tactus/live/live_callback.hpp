// What `tactus live` does on the audio thread, apart from any device: the engine's process()
// and copying. The device's input (an instrument, paper §6's first display mode) or the player
// (the second: a file as sound and vibration) feeds the engine; its N actuator outputs go to
// their device channels; the player's sound goes to the sound channels, delayed with --sync by
// the vibration's delay so onsets are felt as they are heard (a delay that moves when the
// settings change: a DelayLine that crossfades). Meters for the status line are
// kept in atomics. Nothing here allocates, locks, throws or does I/O once constructed
// (tests/realtime proves it).
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <vector>

#include "device_stream.hpp"
#include "player.hpp"
#include "tactus/dsp/delay_line.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus::live {

// Device channels, counted from 0.
struct Routing {
    int device_inputs = 0;   // the engine reads (downmixes) all of them; none with a player
    int device_outputs = 0;  // channels the device is opened with
    std::vector<int> actuator_channels;  // one per engine actuator output
    std::vector<int> sound_channels;     // the player's channels, in turn (none: no sound)
};

// Levels and load since the last take_meters().
struct Meters {
    float input_peak = 0, output_peak = 0;  // full scale
    double load = 0;                        // the slowest callback's time over its period
    int64_t xruns = 0;                      // since the start
    int64_t frames = 0;                     // since the start
};

// The sync delay of a LiveCallback without --sync.
inline constexpr int kNoSync = -1;

class LiveCallback final : public AudioCallback {
  public:
    // Setup thread; `engine` is prepared with device_inputs (or the player's) channels and
    // actuator_channels.size() outputs; `player` may be null. With a player and a
    // sync_delay_samples of 0 or more (--sync), the sound is delayed by it, and can be moved up
    // to max_vibration_delay_samples() (sync_delay.hpp). Allocates.
    LiveCallback(Engine& engine, Player* player, Routing routing, int sync_delay_samples);
    // Setup thread, once no device calls process() any more.
    ~LiveCallback() override;
    LiveCallback(const LiveCallback&) = delete;
    LiveCallback& operator=(const LiveCallback&) = delete;

    // Audio thread. in: device_inputs channels, out: device_outputs channels, each `frames`
    // samples one after another (non-interleaved); in may be null without inputs.
    void process(const float* in, float* out, int frames) noexcept override;
    // Audio thread: the device reported an over- or underrun.
    void note_xrun() noexcept override { xruns_.fetch_add(1, std::memory_order_relaxed); }

    // Any thread: until called, process() outputs silence and neither the player nor the engine
    // moves (a device's first blocks may go out before its ports are connected).
    void begin() noexcept { begun_.store(true, std::memory_order_release); }
    // Any thread.
    Meters take_meters() noexcept;
    int64_t frames() const { return frames_.load(std::memory_order_relaxed); }
    const Routing& routing() const { return routing_; }
    // Any thread: --sync's delay (kNoSync without), and moving it (crossfaded, at the audio
    // thread's next block; ignored without --sync).
    int sync_delay_samples() const { return sync_target_.load(std::memory_order_relaxed); }
    void set_sync_delay_samples(int samples) noexcept;

  private:
    static constexpr int kChunk = Engine::kMaxBlock;
    void process_chunk(const float* in, int in_stride, float* out, int out_stride, int offset,
                       int count) noexcept;

    Engine& engine_;
    Player* player_;
    Routing routing_;
    std::vector<std::vector<float>> played_;  // one chunk of the player's channels
    std::vector<float*> played_pointers_;
    // The sound channels that play each of the player's channels first: the delay (or the
    // copy) writes straight into them, and the other sound channels copy from them.
    std::vector<float*> sound_pointers_;
    bool sync_ = false;
    DelayLine delay_;                        // --sync: the audio thread's, from sync_target_
    std::atomic<int> sync_target_{kNoSync};  // the delay asked for, clamped to delay_'s ring
    std::vector<const float*> in_pointers_;
    std::vector<float*> out_pointers_;
    // Written by the audio thread: lock-free, or the callback would take a lock.
    static_assert(std::atomic<float>::is_always_lock_free &&
                  std::atomic<double>::is_always_lock_free &&
                  std::atomic<int64_t>::is_always_lock_free);
    std::atomic<float> input_peak_{0}, output_peak_{0};
    std::atomic<double> load_{0};
    std::atomic<int64_t> xruns_{0}, frames_{0};
    std::atomic<bool> begun_{false};
};

}  // namespace tactus::live
