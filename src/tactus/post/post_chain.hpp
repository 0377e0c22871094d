// Post-processing in the paper's order (§6): band-limit to the vibrotactile range, P-channel
// flattening, peak limiter, band-limit again. With an actuator profile, its compensation
// follows the flattening (so the limiter bounds what the actuator receives) and the ceiling is
// at most the actuator's max drive; without one the chain is unchanged. The limiter's ceiling sits
// 1 dB under the output ceiling to leave room for the last band-limit's ringing; a final clip at
// the ceiling makes the bound absolute and counts how often it had to act (it should not: see
// clipped_samples()).
#pragma once

#include <cstdint>

#include "tactus/actuator/compensation.hpp"
#include "tactus/core/params.hpp"
#include "tactus/post/band_limit.hpp"
#include "tactus/post/flattening_filter.hpp"
#include "tactus/post/peak_limiter.hpp"

namespace tactus {

class PostChain {
  public:
    static constexpr int kFirstBandOrder = 8;
    static constexpr int kLastBandOrder = 2;
    static constexpr double kRingingMarginDb = 1.0;

    // May allocate. `actuator` may be null (no compensation).
    void prepare(double sample_rate_hz, const Settings& settings,
                 const ActuatorProfile* actuator = nullptr);
    void reset() noexcept;
    void process(float* samples, int count) noexcept;
    int latency_samples() const { return limiter_.latency_samples(); }
    int64_t clipped_samples() const { return clipped_; }
    double ceiling() const { return ceiling_; }
    const FlatteningFilter& flattening() const { return flatten_; }

  private:
    BandLimit first_band_, last_band_;
    FlatteningFilter flatten_;
    ActuatorCompensation compensation_;
    bool compensate_ = false;
    PeakLimiter limiter_;
    double ceiling_ = 1.0;
    int64_t clipped_ = 0;
};

}  // namespace tactus
