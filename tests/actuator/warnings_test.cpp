// Warnings: at most one line per actuator, naming what the engine fitted (actuator/fit.hpp).
#include "tactus/actuator/warnings.hpp"

#include <gtest/gtest.h>

#include "tactus/io/actuator_file.hpp"
#include "tactus/io/preset.hpp"

namespace tactus {
namespace {

bool contains(const std::string& line, const std::string& text) {
    return line.find(text) != std::string::npos;
}

TEST(ActuatorWarnings, DefaultPresetOnTheVoiceCoilIsClean) {
    EXPECT_TRUE(
        actuator_warnings(load_actuator(resolve_actuator("voice-coil")), Settings{}).empty());
}

TEST(ActuatorWarnings, OneLineSaysWhatWasFittedOnTheLra) {
    const auto w = actuator_warnings(load_actuator(resolve_actuator("lra-175")), Settings{});
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].rfind("lra-175: fitted to its usable band 150-235 Hz: ", 0), 0u) << w[0];
    EXPECT_TRUE(contains(w[0], "mapping.frequency 40-400 Hz -> 156-226 Hz")) << w[0];
    EXPECT_TRUE(contains(w[0], "square harmonics dropped")) << w[0];
    EXPECT_TRUE(contains(w[0], "mapping.frequency.hold on")) << w[0];
    EXPECT_TRUE(contains(w[0], "max drive -3.1 dBFS")) << w[0];
    EXPECT_EQ(w[0].find('\n'), std::string::npos);
    Settings inside;
    inside.set(P::frequency_out_min, 160);
    inside.set(P::frequency_out_max, 220);
    inside.set(P::square_mix_out_max, 0);
    inside.set(P::post_band_high_hz, 235);
    inside.set(P::post_band_low_hz, 150);
    inside.set(P::post_ceiling_db, -4);
    inside.set(P::frequency_hold, 1);
    EXPECT_TRUE(actuator_warnings(load_actuator(resolve_actuator("lra-175")), inside).empty());
}

TEST(ActuatorWarnings, FlutterTheLraCannotPlayIsDroppedInTheSameLine) {
    Settings four;
    apply_preset_file(four, resolve_preset("four-channel"));
    const auto w = actuator_warnings(load_actuator(resolve_actuator("lra-175")), four);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_TRUE(contains(w[0], "NPI flutter dropped")) << w[0];
    EXPECT_TRUE(actuator_warnings(load_actuator(resolve_actuator("voice-coil")), four).empty() ||
                !contains(actuator_warnings(load_actuator(resolve_actuator("voice-coil")), four)[0],
                          "flutter"));
}

TEST(ActuatorWarnings, PressureWithoutDc) {
    Settings s;
    s.set(P::post_band_low_hz, 1.0);  // passes the NPIII range
    const auto w = actuator_warnings(load_actuator(resolve_actuator("voice-coil")), s);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_TRUE(contains(w[0], "post.band 1-1000 Hz -> 20-1000 Hz")) << w[0];
    const ActuatorProfile dc = parse_actuator(
        "displacement_um = 100\nreference_hz = 10\ndc = true\nband_low_hz = 0\nband_high_hz = "
        "1000\n",
        "dc.toml");
    EXPECT_TRUE(actuator_warnings(dc, s).empty());
    s.set(P::pressure_weight, 0.2);  // the pressure component asked for outright
    const auto p = actuator_warnings(load_actuator(resolve_actuator("voice-coil")), s);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_TRUE(contains(p[0], "NPIII pressure dropped")) << p[0];
    EXPECT_TRUE(actuator_warnings(dc, s).empty());
}

TEST(ActuatorWarnings, ErmIsDrivenByIntensity) {
    const auto w = actuator_warnings(load_actuator(resolve_actuator("erm")), Settings{});
    ASSERT_EQ(w.size(), 1u);
    EXPECT_TRUE(contains(w[0], "driven by its intensity")) << w[0];
    EXPECT_TRUE(contains(w[0], "75 ms rise")) << w[0];
}

}  // namespace
}  // namespace tactus
