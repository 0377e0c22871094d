// The most recent input samples, in a power-of-two ring, read back as a contiguous window.
// Analysis frames are cut from it at hop boundaries, so any host block size gives the same
// frames.
#pragma once

#include <cstdint>
#include <vector>

namespace tactus {

class SampleHistory {
  public:
    void prepare(int capacity_samples);  // may allocate
    void reset() noexcept;
    void write(const float* samples, int count) noexcept;
    // Copies the newest `count` samples (oldest first) into `out`; zeros before the stream.
    void read_latest(float* out, int count) const noexcept;
    int64_t written() const { return written_; }

  private:
    std::vector<float> ring_;
    uint64_t mask_ = 0;
    int64_t written_ = 0;
};

}  // namespace tactus
