// The last few seconds of what the engine's analysis reads (the downmixed input and, for several
// channels, their summed loudness power: one lane each), written by the audio thread and read
// by a control thread that primes a pipeline for a structural change (engine.hpp): the new
// pipeline hears the same recent past, so its onset history, loudness and envelopes are those
// of the one it replaces. Lock-free, as a sequence lock: the count written (one for every lane)
// is released after each write; samples are stored with release and loaded with acquire (plain
// moves on x86), so a reader that copied a sample of a write not yet counted sees at least the
// count before that write when it checks again afterwards, and the samples that write may have
// overwritten (at most max_write beyond the count) are outside what it accepts. No fences:
// ThreadSanitizer checks the orderings as written.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

namespace tactus {

class InputRing {
  public:
    // Allocates. `max_write`: the largest count write() is given.
    void prepare(int lanes, int64_t capacity, int max_write);
    void reset() noexcept;
    int lanes() const noexcept { return lanes_; }
    // Audio thread: count samples of each lane.
    void write(const float* const* lanes, int count) noexcept;
    // Any thread: samples written since reset.
    int64_t written() const noexcept { return written_.load(std::memory_order_acquire); }
    int64_t capacity() const noexcept { return capacity_; }
    // Any thread: copies samples [from, from + count) of each lane; false when they are no
    // longer (or not yet) held, or within max_write of being overwritten.
    bool read(int64_t from, float* const* lanes, int count) const noexcept;

  private:
    // Accessed through std::atomic_ref: allocated without clearing (input_ring.cpp).
    std::unique_ptr<float[]> samples_;
    int64_t capacity_ = 0;  // per lane; lane l is samples_[l * capacity_ ...]
    int lanes_ = 0;
    int max_write_ = 0;
    std::atomic<int64_t> written_{0};
};

}  // namespace tactus
