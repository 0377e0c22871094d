#include "tactus/post/flattening_filter.hpp"

#include <algorithm>
#include <utility>

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

// The contour's reference scan (thousands of threshold evaluations) and the fit.
FlatteningFilter::Design FlatteningFilter::make_design(double sample_rate_hz,
                                                       const FlatteningDesign& inputs) {
    const double low_hz = inputs.low_hz;
    double high_hz = inputs.high_hz;
    FlatteningFilter filter;
    filter.design_ = inputs;
    // The contour's largest value in the band: on the fitting grid and, for a maximum between
    // its points (small contacts: the summation ramp at 40-80 Hz), on a finer scan.
    high_hz = FittedEq::highest_fitted_hz(high_hz, sample_rate_hz);
    double& reference_db = filter.reference_db_;
    reference_db = -1e9;
    for (double f : FittedEq::grid({.low_hz = low_hz, .high_hz = high_hz}))
        reference_db = std::max(reference_db, filter.contour_db(f));
    for (double f = low_hz; f < high_hz; f *= kScanRatio)
        reference_db = std::max(reference_db, filter.contour_db(f));
    return {inputs, reference_db,
            FittedEq::fit(sample_rate_hz, {.low_hz = low_hz, .high_hz = high_hz},
                          [&filter](double f) { return filter.target_db(f); })};
}
}  // namespace tactus
