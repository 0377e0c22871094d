#include "tactus/post/flattening_filter.hpp"

#include <algorithm>

#include "tactus/perception/sensation.hpp"

namespace tactus {
namespace {
constexpr double kScanRatio = 1.001;
}  // namespace

double FlatteningFilter::contour_db(double frequency_hz) const {
    return perception::threshold_db(perception::Channel::P,
                                    std::max(frequency_hz, perception::kPLowEdgeHz),
                                    {.contact_area_cm2 = design_.contact_area_cm2});
}

double FlatteningFilter::target_db(double frequency_hz) const {
    const double spread = (reference_db_ - contour_db(frequency_hz)) *
                          perception::contour_relief_fraction(design_.level_db);
    return -std::min(design_.strength * spread, design_.range_db);
}

void FlatteningFilter::prepare(double sample_rate_hz, double low_hz, double high_hz,
                               const FlatteningDesign& design) {
    design_ = design;
    // The contour's largest value in the band: on the fitting grid and, for a maximum between
    // its points (small contacts: the summation ramp at 40-80 Hz), on a finer scan.
    high_hz = FittedEq::highest_fitted_hz(high_hz, sample_rate_hz);
    reference_db_ = -1e9;
    for (double f : FittedEq::grid(low_hz, high_hz))
        reference_db_ = std::max(reference_db_, contour_db(f));
    for (double f = low_hz; f < high_hz; f *= kScanRatio)
        reference_db_ = std::max(reference_db_, contour_db(f));
    eq_.design(sample_rate_hz, low_hz, high_hz, [this](double f) { return target_db(f); });
}

}  // namespace tactus
