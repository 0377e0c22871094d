// One mapping of the vibration program: a source feature, its input range, an output range, a
// curve and one-pole smoothing; all data from the preset (paper §6: loudness -> amplitude,
// brightness -> frequency on a log scale, tonality -> sine/square mix).
//   lin: out linear in in.   log: equal input ratios give equal output ratios (frequency scale).
//   exp: linear input (dB), output on a ratio scale (amplitude).
// Inputs outside [in_min, in_max] are clamped; in_min > in_max inverts the mapping.
#pragma once

#include "tactus/analysis/features.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

class FeatureMapping {
  public:
    // `first` is the mapping's *_source parameter; the others follow it in the table.
    void prepare(const Settings& settings, P first, double frames_per_second) noexcept {
        configure(settings, first, frames_per_second);
        smoothed_ = out_min_;
    }
    // Live (audio thread): new ranges, curve, source and smoothing; the smoothed value goes on
    // from where it is.
    void configure(const Settings& settings, P first, double frames_per_second) noexcept;
    void reset(double value) noexcept { smoothed_ = value; }
    // Maps and smooths one frame's feature value.
    double map(const Features& features) noexcept;
    // Maps one frame's feature value without smoothing: the smoothed value jumps to it.
    double jump(const Features& features) noexcept;
    double current() const { return smoothed_; }
    // The curve alone, without smoothing.
    double shape(double input) const noexcept;
    // The curve read backwards: the input shape() maps to `output` (an output beyond the range
    // gives the nearer end's input).
    double input_for(double output) const noexcept;

  private:
    FeatureSource source_{};
    MappingCurve curve_{};
    double in_min_ = 0, in_max_ = 1, out_min_ = 0, out_max_ = 1;
    // What shape() reads of the ranges, worked out once per configure(): the logs of the input
    // range's ends (floored), the output range's floored low end and the log of the ratio of
    // its ends (an exp per frame where a pow cost twice as much).
    double log_in_lo_ = 0, log_in_hi_ = 0, out_lo_ = 1, log_out_ratio_ = 0;
    double smoothing_ = 0, smoothed_ = 0;
};

}  // namespace tactus
