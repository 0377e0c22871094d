// Warnings: what a preset asks of an actuator that it cannot do, one line each.
#include "tactus/io/actuator_file.hpp"
#include "tactus/actuator/warnings.hpp"

#include <gtest/gtest.h>

namespace tactus {
namespace {

bool any_contains(const std::vector<std::string>& lines, const std::string& text) {
    for (const auto& l : lines)
        if (l.find(text) != std::string::npos) return true;
    return false;
}

TEST(ActuatorWarnings, DefaultPresetOnTheVoiceCoilIsClean) {
    EXPECT_TRUE(
        actuator_warnings(load_actuator(resolve_actuator("voice-coil")), Settings{}).empty());
}

TEST(ActuatorWarnings, FortyHertzOnA175HzLra) {
    const auto w = actuator_warnings(load_actuator(resolve_actuator("lra-175")), Settings{});
    EXPECT_TRUE(
        any_contains(w, "asks for 40 Hz (mapping.frequency) but its usable band is 150-235 Hz"));
    EXPECT_TRUE(any_contains(w, "asks for 400 Hz"));
    EXPECT_TRUE(any_contains(w, "max drive -3.1 dBFS"));
    for (const auto& line : w) {
        EXPECT_EQ(line.find('\n'), std::string::npos);
        EXPECT_EQ(line.rfind("lra-175: ", 0), 0u);
    }
    Settings inside;
    inside.set(P::frequency_out_min, 160);
    inside.set(P::frequency_out_max, 220);
    inside.set(P::envelope_attack_ms, 20);
    inside.set(P::post_ceiling_db, -4);
    EXPECT_TRUE(actuator_warnings(load_actuator(resolve_actuator("lra-175")), inside).empty());
}

TEST(ActuatorWarnings, PressureWithoutDc) {
    Settings s;
    s.set(P::post_band_low_hz, 1.0);  // passes the NPIII range
    const auto w = actuator_warnings(load_actuator(resolve_actuator("voice-coil")), s);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("NPIII"), std::string::npos);
    const ActuatorProfile dc = parse_actuator(
        "displacement_um = 100\nreference_hz = 10\ndc = true\nband_low_hz = 0\nband_high_hz = "
        "1000\n",
        "dc.toml");
    EXPECT_TRUE(actuator_warnings(dc, s).empty());
    s.set(P::pressure_weight, 0.2);  // the pressure component asked for outright
    EXPECT_TRUE(any_contains(actuator_warnings(load_actuator(resolve_actuator("voice-coil")), s),
                             "pressure.weight = 0.2 asks for NPIII pressure"));
    EXPECT_TRUE(actuator_warnings(dc, s).empty());
}

TEST(ActuatorWarnings, ErmFrequencyFollowsDrive) {
    const auto w = actuator_warnings(load_actuator(resolve_actuator("erm")), Settings{});
    EXPECT_TRUE(any_contains(w, "frequency follows its drive (120-200 Hz)"));
    EXPECT_TRUE(any_contains(w, "rises in 75 ms"));
}

}  // namespace
}  // namespace tactus
