// The weakest drive felt, against closed forms: a flat actuator at its best frequency reads the
// P threshold's minimum (250 Hz) over its displacement; an LRA reads its resonance; a smaller
// contact raises the floor as P's spatial summation says (+3 dB per halving).
#include "tactus/actuator/felt_floor.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tactus/io/actuator_file.hpp"
#include "tactus/perception/threshold.hpp"

namespace tactus {
namespace {

double um_of_db(double db) {
    return std::pow(10.0, db / 20.0);
}

TEST(FeltFloor, FlatActuatorIsFeltBestAt250Hz) {
    ActuatorProfile flat;
    flat.displacement_um = 10;
    flat.band_low_hz = 20;
    flat.band_high_hz = 1000;
    flat.max_drive = 0.5;
    EXPECT_NEAR(felt_floor(flat, perception::kReferenceAreaCm2),
                um_of_db(perception::kPMinimumDb) / (10 * 0.5), 1e-6);
}

TEST(FeltFloor, LraIsItsThresholdAtResonanceOverItsLargestDisplacement) {
    const ActuatorProfile lra = load_actuator(resolve_actuator("lra-175"));
    const double expected =
        um_of_db(perception::p_threshold_db(175.0)) / (lra.displacement_um * lra.max_drive);
    const double floor = felt_floor(lra, perception::kReferenceAreaCm2);
    EXPECT_NEAR(floor, expected, 0.02 * expected);  // the scan's step of 1/48 octave
    EXPECT_LE(floor, expected);
    EXPECT_NEAR(20 * std::log10(floor), -35.5, 0.1);
}

TEST(FeltFloor, SmallerContactRaisesTheFloorAsSpatialSummationSays) {
    const ActuatorProfile lra = load_actuator(resolve_actuator("lra-175"));
    const double reference = felt_floor(lra, perception::kReferenceAreaCm2);
    const double quarter = felt_floor(lra, perception::kReferenceAreaCm2 / 4);
    EXPECT_NEAR(20 * std::log10(quarter / reference), 6.0, 0.1);
}

}  // namespace
}  // namespace tactus
