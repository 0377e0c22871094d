// Actuator compensation: the target is the inverse displacement response inside the usable
// band, bounded to +-12 dB; the measured response (sines through process()) follows it within
// 1 dB for the voice coil and 2 dB for the narrow LRA (figures printed).
#include "tactus/actuator/compensation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "support/signals.hpp"
#include "tactus/io/actuator_file.hpp"

namespace tactus {
namespace {

TEST(ActuatorCompensation, TargetIsTheBoundedInverseResponse) {
    for (const char* name : {"voice-coil", "lra-175", "erm"}) {
        const ActuatorProfile a = load_actuator(resolve_actuator(name));
        ActuatorCompensation c;
        c.prepare({.sample_rate_hz = 48000}, a);
        for (double f = a.band_low_hz; f <= a.band_high_hz; f *= 1.05) {
            EXPECT_NEAR(c.target_db(f), std::clamp(-a.response_db(f), -12.0, 12.0), 1e-9);
            EXPECT_LE(std::abs(c.target_db(f)), ActuatorCompensation::kBoundDb);
        }
        EXPECT_NEAR(c.target_db(a.reference_hz), 0.0, 1e-9) << name;
    }
}

TEST(ActuatorCompensation, VoiceCoilMeasuredResponseFollowsTarget) {
    const ActuatorProfile a = load_actuator(resolve_actuator("voice-coil"));
    for (double fs : {44100.0, 48000.0, 96000.0}) {
        ActuatorCompensation design;
        design.prepare({.sample_rate_hz = fs}, a);
        double worst = 0;
        for (double f = 25.0; f <= 900.0; f *= 1.15) {
            ActuatorCompensation c;
            c.prepare({.sample_rate_hz = fs}, a);
            const double measured =
                test::measured_gain_db([&](float* x, int n) { c.process(x, n); }, f, fs);
            worst = std::max(worst, std::abs(measured - design.target_db(f)));
            EXPECT_NEAR(measured, design.target_db(f), 1.0) << f << " Hz at " << fs;
        }
        std::cout << "[ actuator ] voice-coil compensation at " << fs
                  << " Hz: max |measured - target| over 25-900 Hz = " << worst << " dB\n";
    }
}

TEST(ActuatorCompensation, LraResonanceIsNotchedWithinTheBound) {
    const ActuatorProfile a = load_actuator(resolve_actuator("lra-175"));
    const double fs = 48000;
    ActuatorCompensation design;
    design.prepare({.sample_rate_hz = fs}, a);
    double worst = 0;
    for (double f = a.band_low_hz; f <= a.band_high_hz; f *= 1.03) {
        ActuatorCompensation c;
        c.prepare({.sample_rate_hz = fs}, a);
        const double measured =
            test::measured_gain_db([&](float* x, int n) { c.process(x, n); }, f, fs);
        worst = std::max(worst, std::abs(measured - design.target_db(f)));
        EXPECT_NEAR(measured, design.target_db(f), 2.0) << f << " Hz";
    }
    std::cout << "[ actuator ] lra-175 compensation: max |measured - target| over 150-235 Hz = "
              << worst << " dB\n";
    EXPECT_NEAR(design.magnitude_db(175), 0.0, 1.5);  // the resonance is cut to the reference
    for (double f = 10; f <= 5000; f *= 1.05)         // and nothing is boosted beyond the bound
        EXPECT_LE(design.magnitude_db(f), ActuatorCompensation::kBoundDb + 0.5) << f;
}

TEST(ActuatorCompensation, FlattensTheVoiceCoilDisplacement) {
    // Compensation followed by the actuator: displacement within 1 dB of the reference level
    // wherever the bound is not reached.
    const ActuatorProfile a = load_actuator(resolve_actuator("voice-coil"));
    ActuatorCompensation c;
    c.prepare({.sample_rate_hz = 48000}, a);
    for (double f = 25; f <= 400; f *= 1.1)
        EXPECT_NEAR(c.magnitude_db(f) + a.response_db(f), 0.0, 1.0) << f;
}

}  // namespace
}  // namespace tactus
