// The fit of the default mapping to an actuator: the frequency range lands inside the usable
// band (kEdgeMargin inside its edges) with the features' order kept and the in-band part of the
// mapping as it was (a clamp at kFrequencySpread 1); what the actuator cannot play is dropped;
// the voice coil is left alone.
#include "tactus/actuator/fit.hpp"

#include <gtest/gtest.h>

#include "tactus/io/actuator_file.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/mapping/feature_mapping.hpp"

namespace tactus {
namespace {

// The vibration frequency a settings' mapping gives a brightness.
double frequency_at(const Settings& s, double brightness_hz) {
    FeatureMapping m;
    m.configure(s, P::frequency_source, 100);
    return m.shape(brightness_hz);
}

TEST(ActuatorFit, VoiceCoilKeepsTheDefaultMapping) {
    const ActuatorFit fit =
        fit_to_actuator(load_actuator(resolve_actuator("voice-coil")), Settings{});
    EXPECT_EQ(fit.settings, Settings{});
    EXPECT_TRUE(fit.note.empty());
}

TEST(ActuatorFit, LraFrequenciesStayInItsBandInOrder) {
    const ActuatorProfile a = load_actuator(resolve_actuator("lra-175"));
    const Settings s;
    const Settings fitted = fit_to_actuator(a, s).settings;
    double previous = 0;
    for (double b = 30; b < 5000; b *= 1.1) {
        const double f = frequency_at(fitted, b);
        EXPECT_GE(f, a.band_low_hz * kEdgeMargin - 1e-6);
        EXPECT_LE(f, a.band_high_hz / kEdgeMargin + 1e-6);
        EXPECT_GE(f, previous - 1e-9);
        previous = f;
        const double before = frequency_at(s, b);
        if (before > a.band_low_hz * kEdgeMargin && before < a.band_high_hz / kEdgeMargin &&
            kFrequencySpread == 1.0) {
            EXPECT_NEAR(f, before, 1e-6 * before);
        }
    }
    // A kick and a snare (tfd's body brightness: Sonic Pi's kicks 60-110 Hz, snares 290-530 Hz)
    // at the band's two ends.
    EXPECT_NEAR(frequency_at(fitted, 110), a.band_low_hz * kEdgeMargin, 1e-6);
    EXPECT_NEAR(frequency_at(fitted, 290), a.band_high_hz / kEdgeMargin, 1e-6);
    EXPECT_EQ(fitted[P::square_mix_out_max], 0.0);
    EXPECT_EQ(fitted[P::post_band_low_hz], a.band_low_hz);
    EXPECT_EQ(fitted[P::post_band_high_hz], a.band_high_hz);
}

TEST(ActuatorFit, AnLraHoldsOneFrequencyPerPulse) {
    const ActuatorProfile lra = load_actuator(resolve_actuator("lra-175"));
    EXPECT_EQ(fit_to_actuator(lra, Settings{}).settings[P::frequency_hold], 1.0);
    for (const char* other : {"voice-coil", "erm"})
        EXPECT_EQ(fit_to_actuator(load_actuator(resolve_actuator(other)), Settings{})
                      .settings[P::frequency_hold],
                  0.0)
            << other;
}

TEST(ActuatorFit, WhatTheActuatorCannotPlayIsDropped) {
    Settings four;
    apply_preset_file(four, resolve_preset("four-channel"));
    four.set(P::pressure_weight, 0.3);
    for (const char* name : {"lra-175", "erm"}) {
        const Settings fitted =
            fit_to_actuator(load_actuator(resolve_actuator(name)), four).settings;
        EXPECT_EQ(fitted[P::flutter_weight], 0.0) << name;
        EXPECT_EQ(fitted[P::pressure_weight], 0.0) << name;
    }
    const Settings coil =
        fit_to_actuator(load_actuator(resolve_actuator("voice-coil")), four).settings;
    EXPECT_EQ(coil[P::flutter_weight], four[P::flutter_weight]);  // 2-40 Hz: it plays it
}

TEST(ActuatorFit, ADescendingRangeStaysDescending) {
    const ActuatorProfile a = load_actuator(resolve_actuator("lra-175"));
    Settings s;
    s.set(P::frequency_out_min, 400);
    s.set(P::frequency_out_max, 40);
    const Settings fitted = fit_to_actuator(a, s).settings;
    EXPECT_GT(frequency_at(fitted, 100), frequency_at(fitted, 1900));
    EXPECT_NEAR(frequency_at(fitted, 30), a.band_high_hz / kEdgeMargin, 1e-6);
}

}  // namespace
}  // namespace tactus
