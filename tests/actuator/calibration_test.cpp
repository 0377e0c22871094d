// Farina's sweep measurement (actuator/calibration.hpp) against a known actuator: the lra-175
// profile's band-pass resonance as a filter (its magnitude is the profile's response term), after
// a device delay, with harmonic distortion added; the measured profile matches the shipped one
// within 1 dB over its usable band. Profiles written as text read back as the same profile.
#include "tactus/actuator/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "tactus/io/actuator_file.hpp"

namespace tactus {
namespace {

ActuatorProfile shipped(const char* name) {
    return load_actuator(std::filesystem::path(TACTUS_SOURCE_DIR) / "actuators" /
                         (std::string(name) + ".toml"));
}

// The profile's band-pass resonance, bilinear with the centre prewarped (RBJ's constant-peak
// band-pass), after `delay` samples of silence; `distortion` adds a square term.
std::vector<float> through_resonance(const std::vector<float>& x, const ActuatorProfile& a,
                                     double rate_hz, size_t delay, double distortion) {
    const double w0 = 2 * M_PI * a.resonance_hz / rate_hz, alpha = std::sin(w0) / (2 * a.q);
    const double a0 = 1 + alpha, b0 = alpha / a0, b2 = -alpha / a0, a1 = -2 * std::cos(w0) / a0,
                 a2 = (1 - alpha) / a0;
    std::vector<float> y(delay + x.size() + static_cast<size_t>(rate_hz));
    double z1 = 0, z2 = 0;
    for (size_t i = 0; i < y.size() - delay; ++i) {
        const double in = i < x.size() ? x[i] : 0.0;
        const double out = b0 * in + z1;
        z1 = -a1 * out + z2;
        z2 = b2 * in - a2 * out;
        y[delay + i] = static_cast<float>(out + distortion * out * out);
    }
    return y;
}

void expect_matches_over_band(const ActuatorProfile& measured, const ActuatorProfile& truth) {
    for (double f = truth.band_low_hz; f <= truth.band_high_hz; f *= std::exp2(1.0 / 48))
        EXPECT_NEAR(measured.response_db(f), truth.response_db(f), 1.0) << f << " Hz";
}

TEST(Calibration, MeasuresTheLraResonanceWithinOneDecibel) {
    const ActuatorProfile lra = shipped("lra-175");
    const SweepSpec spec{.sample_rate_hz = 48000, .low_hz = 20, .high_hz = 2000, .seconds = 4};
    const std::vector<float> sweep = exponential_sweep(spec);
    const std::vector<float> recorded =
        through_resonance(sweep, lra, spec.sample_rate_hz, 1234, 0.2);
    const auto measured = measure_response(sweep, recorded, spec);
    const ActuatorProfile with_base = measured_profile(measured, &lra);
    expect_matches_over_band(with_base, lra);
    EXPECT_EQ(with_base.resonance, ResonanceKind::none) << "the points are the response";
    const ActuatorProfile alone = measured_profile(measured, nullptr);
    EXPECT_NEAR(alone.reference_hz, 175, 175 * (std::exp2(1.0 / 12) - 1)) << "the peak";
    expect_matches_over_band(alone, lra);
    EXPECT_LT(alone.band_low_hz, lra.band_low_hz);  // 12 dB down: wider than the shipped band
}

TEST(Calibration, SilenceIsNoMeasurement) {
    const SweepSpec spec{.sample_rate_hz = 48000, .seconds = 1};
    const std::vector<float> silence(96000);
    EXPECT_THROW(measure_response(exponential_sweep(spec), silence, spec), std::runtime_error);
    EXPECT_THROW(exponential_sweep({.sample_rate_hz = 8000, .high_hz = 5000}),
                 std::invalid_argument);
}

TEST(ActuatorText, ReadsBackAsTheSameProfile) {
    for (const char* name : {"voice-coil", "lra-175", "erm"}) {
        const ActuatorProfile p = shipped(name);
        EXPECT_EQ(parse_actuator(actuator_text(p, "a comment\non two lines"), "x.toml"), p) << name;
    }
    ActuatorProfile odd = shipped("voice-coil");
    odd.name = "quote \" and \\ back";
    odd.points = {{20.5, -3.25}, {100, 0}, {1000.125, 1e-5}};
    odd.reference_hz = 1.0 / 3;
    EXPECT_EQ(parse_actuator(actuator_text(odd, ""), "x.toml"), odd);
}

}  // namespace
}  // namespace tactus
