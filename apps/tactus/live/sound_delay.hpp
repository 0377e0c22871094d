// --sync's delay line: the player's sound held back by the time from an onset to its pulse
// (sync_delay.hpp), so that each onset is heard when it is felt (paper §6). That time changes
// with the settings, so the delay moves while the sound plays: each channel's ring is allocated
// once for the longest delay the measurement can give, and a new delay is reached by a
// crossfade from the old read position to the new one (as the engine hands over a structural
// change: Engine::kCrossfadeMs), so the sound never clicks; it skips or repeats a few
// milliseconds instead.
#pragma once

#include <atomic>
#include <vector>

namespace tactus::live {

class SoundDelay {
  public:
    // Setup thread; allocates `channels` rings of max_delay_samples + 1. `delay_samples` is
    // clamped to 0 ... max_delay_samples.
    SoundDelay(int channels, int max_delay_samples, int delay_samples, int fade_samples);

    // Any thread: the delay to move to, clamped to 0 ... max_delay_samples(); the audio thread
    // starts its crossfade at its next process() (after the one under way, if any).
    void set_delay_samples(int delay_samples) noexcept;
    // Any thread: the delay asked for last.
    int delay_samples() const noexcept { return target_.load(std::memory_order_relaxed); }
    int max_delay_samples() const noexcept { return size_ - 1; }

    // Audio thread: `count` samples of each of the channels, delayed in place.
    void process(float* const* channels, int count) noexcept;

  private:
    std::vector<std::vector<float>> rings_;
    int size_ = 1;
    int write_ = 0;       // where the next input sample goes, in every ring
    int delay_ = 0;       // audio thread: the delay read from
    int next_delay_ = 0;  // the delay faded to, while fading
    int fade_done_ = 0;   // samples of the crossfade done
    int fade_samples_ = 1;
    bool fading_ = false;
    std::atomic<int> target_{0};
};

}  // namespace tactus::live
