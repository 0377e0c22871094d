// The one-pole glide every synthesis parameter follows towards the value the last control frame
// set (so frame steps do not click). A sample holds the parameter at its own instant and the
// glide steps after it, so the samples lie on the same continuous curve at any rate (the engine
// synthesises below the input rate: engine.hpp); mean() is the exact mean over the coming
// sample, with which a frequency integrates into a phase without a rate-dependent lag. A glide
// towards 0 ends in exact 0, so silence stays exact.
#pragma once

#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

// Time constant of a one-pole whose corner is `corner_hz`: 1 / (2 pi f).
constexpr double corner_time_constant_ms(double corner_hz) {
    return 1e3 / (2.0 * kPi * corner_hz);
}

class Glide {
  public:
    void prepare(const ProcessSpec& spec, double time_constant_ms) {
        coefficient_ = one_pole_coefficient(time_constant_ms, spec.sample_rate_hz);
        mean_fraction_ = coefficient_ > 0.0 ? (1.0 - coefficient_) / -std::log(coefficient_) : 0.0;
    }
    // `value` one sample on towards `target`.
    double step(double value, double target) const noexcept {
        const double next = target + coefficient_ * (value - target);
        return target == 0.0 && std::fabs(next) < kSilent ? 0.0 : next;
    }
    // The mean of the glide from `value` towards `target` over the coming sample.
    double mean(double value, double target) const noexcept {
        return target + mean_fraction_ * (value - target);
    }

  private:
    static constexpr double kSilent = 1e-9;
    double coefficient_ = 0.0, mean_fraction_ = 0.0;
};

}  // namespace tactus
