#include "tactus/actuator/felt_floor.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/perception/threshold.hpp"

namespace tactus {
namespace {

constexpr double kStepsPerOctave = 48;  // the band scanned this finely (a Q of 20 spans 3 steps)

}  // namespace

double felt_floor(const ActuatorProfile& actuator, double contact_area_cm2) {
    const perception::Stimulus stimulus{.contact_area_cm2 = contact_area_cm2,
                                        .duration_s = perception::kReferenceDurationS};
    const double low_hz = std::max(actuator.band_low_hz, perception::kPLowEdgeHz);
    const double high_hz = std::min(actuator.band_high_hz, perception::kPHighEdgeHz);
    const double octaves = std::max(0.0, std::log2(high_hz / low_hz));
    const int steps = std::max(1, static_cast<int>(std::ceil(octaves * kStepsPerOctave)));
    double floor = 1.0;
    for (int i = 0; i <= steps; ++i) {
        const double f = low_hz * std::exp2(octaves * i / steps);
        const double largest_um = actuator.displacement_um_at(f) * actuator.max_drive;
        if (largest_um > 0)
            floor = std::min(
                floor, db_to_gain(perception::detection_threshold_db(f, stimulus)) / largest_um);
    }
    return floor;
}

}  // namespace tactus
