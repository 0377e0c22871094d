// P-channel flattening filter (paper §6: "a frequency flattening function to compensate for the
// non-linear response of the upper ranges of vibrotaction (P channel)").
// Target: equal sensation at threshold, i.e. gain(f) = strength * (T_P(f) - T_max) where T_P is
// the P threshold curve (perception/threshold.hpp), held flat below 40 Hz (there NPI sets the
// threshold, flat 20-40 Hz: paper §3.2) and T_max is the largest in the band: the filter only
// attenuates, the least sensitive frequency passes at unity. The level spread is bounded by
// range_db. Realised as a cascade of half-octave peaking biquads whose gains are fitted to the
// target by damped Gauss-Newton least squares in dB on a log-frequency grid (the "accurate
// graphic equaliser" design idea of Välimäki & Liski 2017).
#pragma once

#include <array>
#include <vector>

#include "tactus/post/biquad.hpp"

namespace tactus {

class FlatteningFilter {
  public:
    static constexpr int kMaxSections = 16;

    void prepare(double sample_rate_hz, double low_hz, double high_hz, double strength,
                 double range_db);  // may allocate (design)
    void reset() noexcept;
    void process(float* samples, int count) noexcept;

    double target_db(double frequency_hz) const;     // what the design aims for
    double magnitude_db(double frequency_hz) const;  // what it achieves

  private:
    double sample_rate_hz_ = 48000, strength_ = 1, range_db_ = 30, reference_db_ = 0;
    double low_hz_ = 20, high_hz_ = 1000;
    std::array<Biquad, kMaxSections> sections_;
    int count_ = 0;
    double gain_ = 1.0;
};

}  // namespace tactus
