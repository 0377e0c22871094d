// A multichannel delay line: each channel's ring is allocated once for the longest delay it
// will be asked for, and process() is real-time safe. The delay may change while the sound
// plays, per block: at once (a pass-through that follows the engine's latency, in step with
// the engine's own hand-over), or by a crossfade of fade_samples from the old read position
// to the new one, so the sound never clicks (it skips or repeats a few milliseconds instead).
// One thread (the audio thread) calls everything but prepare().
#pragma once

#include <vector>

namespace tactus {

class DelayLine {
  public:
    // Setup thread; allocates `channels` rings of max_delay_samples + 1 and starts silent at
    // delay_samples (clamped to 0 ... max_delay_samples). fade_samples of 0 or 1: changes are
    // immediate.
    void prepare(int channels, int max_delay_samples, int delay_samples, int fade_samples = 0);
    // Silence in the rings, the delay as asked for last, no crossfade under way.
    void reset() noexcept;

    // The delay from the next process() on, clamped to 0 ... max_delay_samples(). With a
    // crossfade, a change asked for while one is under way starts when that one ends.
    void set_delay_samples(int delay_samples) noexcept;
    int delay_samples() const noexcept { return target_; }  // asked for last
    int max_delay_samples() const noexcept { return size_ - 1; }
    int channels() const noexcept { return static_cast<int>(rings_.size()); }

    // `count` samples of every channel, in[c] delayed into out[c] (the same buffer, or not).
    void process(const float* const* in, float* const* out, int count) noexcept;
    void process(float* const* channels, int count) noexcept { process(channels, channels, count); }

  private:
    std::vector<std::vector<float>> rings_;
    int size_ = 1;
    int write_ = 0;       // where the next input sample goes, in every ring
    int delay_ = 0;       // the delay read from
    int next_delay_ = 0;  // the delay faded to, while fading
    int target_ = 0;      // the delay asked for
    int fade_done_ = 0;   // samples of the crossfade done
    int fade_samples_ = 1;
    bool fading_ = false;
};

}  // namespace tactus
