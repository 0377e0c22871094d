// A magnitude response drawn to order: a cascade of half-octave peaking biquads across
// [low_hz, high_hz] plus an overall gain, the section gains fitted to a target curve (dB) by
// damped Gauss-Newton least squares in dB on a log-frequency grid (the "accurate graphic
// equaliser" design idea of Välimäki & Liski 2017). Used by the flattening filter (a perception
// target) and the actuator compensation (an inverse actuator response).
#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

#include "tactus/dsp/biquad.hpp"

namespace tactus {

class FittedEq {
  public:
    static constexpr int kMaxSections = 16;
    static constexpr int kGridPoints = 96;

    // The log-frequency grid the fit is made on (and a target's extremes are best taken on).
    static std::vector<double> grid(double low_hz, double high_hz);
    static double highest_fitted_hz(double high_hz, double sample_rate_hz) {
        return std::min(high_hz, 0.45 * sample_rate_hz);
    }

    // May allocate. The target is sampled on grid(low_hz, highest_fitted_hz(high_hz, fs)).
    void design(double sample_rate_hz, double low_hz, double high_hz,
                const std::function<double(double frequency_hz)>& target_db);
    void reset() noexcept;
    void process(float* samples, int count) noexcept;
    double magnitude_db(double frequency_hz) const;  // what it achieves

  private:
    double sample_rate_hz_ = 48000;
    std::array<Biquad, kMaxSections> sections_;
    int count_ = 0;
    double gain_ = 1.0;
};

}  // namespace tactus
