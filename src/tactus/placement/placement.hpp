// Actuator placement in a tonehole (paper §4, Figure 2): per hole size, the skin extension
// across every finger of every subject (mean, sample SD with n - 1, range), the recommended
// actuator depth below the surround, and the hole size with the least variation.
//
// Depth rule: mean - SD of the extension (not below 0). A voice coil works best "placed just
// close enough to the skin to be felt" and is damped by the skin pressing on it (§4). At the
// mean, about half the fingers would not reach the actuator at all and feel nothing; at
// mean - SD about 84 % of fingers touch it (for normally spread extensions), and the typical
// finger presses on it by only about one SD. With one measurement for a hole, the depth is it.
//
// Least variation: the smallest SD among holes with at least two measurements (ties: the
// smaller hole), the paper's criterion for an interface shared by several players and fingers.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "tactus/placement/measurements.hpp"

namespace tactus {

struct HoleSummary {
    double hole_mm = 0;
    int n = 0;                                              // measurements (fingers x subjects)
    int subjects = 0;                                       // distinct subjects
    double mean_mm = 0, sd_mm = 0, min_mm = 0, max_mm = 0;  // sd_mm NaN when n < 2
    double depth_mm = 0;  // recommended actuator depth below the surround's outer surface
};

struct PlacementReport {
    std::vector<HoleSummary> holes;         // ascending hole size
    std::optional<size_t> least_variation;  // index into holes; none if no hole has n >= 2
};

PlacementReport summarise_placement(std::span<const Measurement> measurements);

}  // namespace tactus
