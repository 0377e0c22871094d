// Look-ahead peak limiter with a soft knee and a hard ceiling (the role of omx.peaklim~ in the
// paper, §6: "dynamic range is then reduced so that quieter vibrotactile events are not lost").
// Each sample's magnitude p asks for the output level
//   p                          for p <= T
//   T + (C - T) u / (1 + u)    above, u = (p - T) / (C - T): slope 1 at T, rising with p and
// approaching C only as 1/u, so louder input always gives louder output (the order of dynamics
// is kept) even 60 dB over the knee. The required gain
// is held for the look-ahead (sliding minimum) and averaged over it (box filter), which
// guarantees the gain is fully down when the peak leaves the delay line; recovery is a one-pole
// release. Non-finite input is treated as 0. Drive, threshold and ceiling are live: set_levels()
// glides them linearly per sample (audio thread); the look-ahead is structural (prepare).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tactus/dsp/process_spec.hpp"

namespace tactus {

// The limiter's levels, by name: no two of them can be swapped at a call.
struct LimiterLevels {
    double drive_db = 12;      // gain into the limiter
    double threshold_db = -6;  // soft knee start, relative to the ceiling
    double ceiling = 1;        // hard output bound, full scale
    double release_ms = 80;    // gain recovery time constant
};

class PeakLimiter {
  public:
    void prepare(const ProcessSpec& spec, double lookahead_ms,
                 const LimiterLevels& levels);  // may allocate
    // Audio thread: drive, threshold and ceiling glide to `levels` over `samples` samples (at
    // once when 0); the release applies at once.
    void set_levels(const LimiterLevels& levels, int samples) noexcept;
    void reset() noexcept;
    void process(float* samples, int count) noexcept;
    int latency() const { return lookahead_; }
    // The output level the static curve gives a sample of magnitude `peak` (after drive).
    double curve(double peak) const noexcept;

  private:
    struct Gains {
        double drive = 1, threshold = 0.5, ceiling = 1;
    };
    static Gains gains_of(const LimiterLevels& levels) noexcept;
    int lookahead_ = 1;
    double sample_rate_hz_ = 48000, release_ = 0;
    double drive_ = 1, threshold_ = 0.5, ceiling_ = 1;  // now
    Gains target_, step_;                               // a glide: per-sample steps
    int glide_left_ = 0;
    std::vector<double> delay_;      // look-ahead delay line (double: no overflow)
    std::vector<double> held_gain_;  // ring for the box average
    std::vector<std::pair<int64_t, double>> minimum_;  // monotonic deque (ring) for sliding min
    size_t minimum_head_ = 0, minimum_size_ = 0;
    int64_t time_ = 0;
    size_t slot_ = 0;  // time_ modulo the look-ahead
    double released_gain_ = 1, box_sum_ = 0;
    // held_gain_[0 ... slot_) summed in order as they are written: at the ring's end, the exact
    // re-sum that ends the drift, without a pass over the look-ahead in one sample.
    double fresh_sum_ = 0;
};

}  // namespace tactus
