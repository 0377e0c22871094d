#include "tactus/mapping/feature_mapping.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {
P offset(P first, int k) {
    return static_cast<P>(static_cast<int>(first) + k);
}
constexpr double kSmallest = 1e-9;  // keeps log curves finite at 0
}  // namespace

void FeatureMapping::configure(const Settings& s, P first, double frames_per_second) noexcept {
    source_ = static_cast<FeatureSource>(static_cast<int>(s[first]));
    in_min_ = s[offset(first, 1)];
    in_max_ = s[offset(first, 2)];
    out_min_ = s[offset(first, 3)];
    out_max_ = s[offset(first, 4)];
    curve_ = static_cast<MappingCurve>(static_cast<int>(s[offset(first, 5)]));
    smoothing_ = one_pole_coefficient(s[offset(first, 6)], frames_per_second);
    log_in_lo_ = std::log(std::max(in_min_, kSmallest));
    log_in_hi_ = std::log(std::max(in_max_, kSmallest));
    out_lo_ = std::max(out_min_, kSmallest);
    log_out_ratio_ = std::log(std::max(out_max_, kSmallest) / out_lo_);
}

double FeatureMapping::shape(double input) const noexcept {
    double t = 0.0;
    if (curve_ == MappingCurve::log) {
        const double lo = log_in_lo_, hi = log_in_hi_;
        t = hi != lo ? (std::log(std::max(input, kSmallest)) - lo) / (hi - lo) : 0.0;
    } else {
        t = in_max_ != in_min_ ? (input - in_min_) / (in_max_ - in_min_) : 0.0;
    }
    t = std::clamp(t, 0.0, 1.0);
    if (curve_ == MappingCurve::lin) return out_min_ + t * (out_max_ - out_min_);
    return out_lo_ * std::exp(t * log_out_ratio_);
}

double FeatureMapping::input_for(double output) const noexcept {
    double t = 0.0;
    if (curve_ == MappingCurve::lin) {
        t = out_max_ != out_min_ ? (output - out_min_) / (out_max_ - out_min_) : 0.0;
    } else {
        const double lo = std::log(std::max(out_min_, kSmallest));
        const double hi = std::log(std::max(out_max_, kSmallest));
        t = hi != lo ? (std::log(std::max(output, kSmallest)) - lo) / (hi - lo) : 0.0;
    }
    t = std::clamp(t, 0.0, 1.0);
    if (curve_ != MappingCurve::log) return in_min_ + t * (in_max_ - in_min_);
    const double lo = std::max(in_min_, kSmallest), hi = std::max(in_max_, kSmallest);
    return lo * std::pow(hi / lo, t);
}

double FeatureMapping::map(const Features& features) noexcept {
    const double target = shape(feature_value(features, source_));
    if (!std::isfinite(target)) return smoothed_;  // hold rather than pass NaN to the synth
    smoothed_ = target + smoothing_ * (smoothed_ - target);
    return smoothed_;
}

double FeatureMapping::jump(const Features& features) noexcept {
    const double target = shape(feature_value(features, source_));
    if (std::isfinite(target)) smoothed_ = target;
    return smoothed_;
}

}  // namespace tactus
