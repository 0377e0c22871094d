// Actuator profiles: the shipped TOML files load and describe their actuator class (voice coil:
// flat displacement below resonance, -12 dB/octave above; LRA: a narrow peak at f0; no DC
// without DC capability), and bad files give one-line errors naming file, line and key.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <fstream>

#include "support/temp_dir.hpp"
#include "tactus/io/actuator_file.hpp"

namespace tactus {
namespace {

TEST(ActuatorProfile, ShippedProfilesLoad) {
    for (const char* name : {"voice-coil", "lra-175", "erm"}) {
        const ActuatorProfile a = load_actuator(resolve_actuator(name));
        EXPECT_EQ(a.name, name);
        EXPECT_FALSE(a.description.empty());
        EXPECT_NEAR(a.response_db(a.reference_hz), 0.0, 1e-12) << name;
        EXPECT_NEAR(a.displacement_um_at(a.reference_hz), a.displacement_um, 1e-9) << name;
        EXPECT_FALSE(a.dc) << name;  // none of them holds an offset (paper §5.4)
        EXPECT_EQ(a.response_db(0.0), -INFINITY) << name;
    }
    EXPECT_EQ(load_actuator(resolve_actuator("lra-175")).type, ActuatorType::lra);
    EXPECT_EQ(load_actuator(resolve_actuator("erm")).type, ActuatorType::erm);
}

TEST(ActuatorProfile, VoiceCoilIsAMassSpring) {
    const ActuatorProfile a = load_actuator(resolve_actuator("voice-coil"));
    EXPECT_NEAR(a.response_db(40) - a.response_db(25), 0.0, 0.5);      // flat below Fs
    EXPECT_GT(a.response_db(200), a.response_db(100));                 // skin-damped peak
    EXPECT_NEAR(a.response_db(800) - a.response_db(400), -12.0, 1.5);  // mass-controlled
    EXPECT_NEAR(a.response_db(5) - a.response_db(10), -12.0, 0.3);     // AC-coupled, no DC
}

TEST(ActuatorProfile, LraIsNarrow) {
    const ActuatorProfile a = load_actuator(resolve_actuator("lra-175"));
    for (double f = 100; f <= 400; f *= 1.02) EXPECT_LE(a.response_db(f), 1e-9) << f;
    EXPECT_LT(a.response_db(150), -9.0);
    EXPECT_LT(a.response_db(235), -9.0);
    EXPECT_LT(a.response_db(40), -30.0);
    EXPECT_TRUE(a.in_band(175));
    EXPECT_FALSE(a.in_band(40));
}

TEST(ActuatorProfile, TablePointsAndDcCapability) {
    const ActuatorProfile a = parse_actuator(R"(
        displacement_um = 100
        reference_hz = 10
        dc = true
        band_low_hz = 0
        band_high_hz = 100
        [response]
        points = [[10, 0], [40, -6]]
    )",
                                             "dc.toml");
    EXPECT_NEAR(a.response_db(0.0), 0.0, 1e-12);  // flat to a static offset
    EXPECT_NEAR(a.response_db(20), -3.0, 1e-9);   // linear on log-frequency
    EXPECT_NEAR(a.response_db(60), -6.0, 1e-9);
    EXPECT_NEAR(a.response_db(200), -6.0 - 12.0, 1e-9);  // rolls off above the band
    EXPECT_EQ(a.name, "dc");
}

std::string error_of(const std::string& text) {
    try {
        parse_actuator(text, "bad.toml");
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(ActuatorProfile, OneLineErrorsNameFileLineAndKey) {
    const std::string base =
        "displacement_um = 10\nreference_hz = 100\nband_low_hz = 20\n"
        "band_high_hz = 500\n";
    const struct {
        std::string text, expect;
    } cases[] = {
        {"reference_hz = 100\nband_low_hz = 20\nband_high_hz = 500\n", "displacement_um: missing"},
        {base + "q = 2\n", "bad.toml:5:5: q: unknown key"},
        {base + "[response]\nkind = \"low-pass\"\nresonance_hz = 200\nq = 1000\n",
         "bad.toml:8:5: response.q: 1000 is out of range"},
        {base + "type = \"piezo\"\n", "type: must be one of: voice-coil, lra, erm"},
        {base + "dc = 1\n", "dc: must be true or false"},
        {"displacement_um = 10\nreference_hz = 100\nband_low_hz = 200\nband_high_hz = 100\n",
         "band_high_hz: must be above band_low_hz"},
        {base + "[response]\npoints = [[100, 0], [50, 1]]\n", "frequencies must increase"},
        {base + "max_drive = 2\n", "max_drive: 2 is out of range"},
        {base + "displacement_um = \n", "TOML syntax error"},
        {base + "type = \"erm\"\n", "needs [erm]"},
        {base + "\"a\\nb\" = 1\n", "a\\nb: unknown key"},  // a key with a newline, escaped
    };
    for (const auto& c : cases) {
        const std::string message = error_of(c.text);
        EXPECT_NE(message.find(c.expect), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_EQ(message.rfind("bad.toml", 0), 0u) << message;
    }
}

class ActuatorLookup : public test::TempDirTest {};

TEST_F(ActuatorLookup, ByNameOrPathWithEnvironmentOverride) {
    EXPECT_EQ(resolve_actuator("voice-coil").filename(), "voice-coil.toml");
    const auto custom = dir_ / "mine.toml";
    std::ofstream(custom) << "displacement_um = 5\nreference_hz = 250\nband_low_hz = 50\n"
                             "band_high_hz = 400\n";
    EXPECT_EQ(resolve_actuator(custom.string()), custom);
    ::setenv("TACTUS_ACTUATOR_PATH", dir_.c_str(), 1);
    EXPECT_EQ(resolve_actuator("mine"), custom);
    EXPECT_EQ(load_actuator(resolve_actuator("mine")).name, "mine");
    ::unsetenv("TACTUS_ACTUATOR_PATH");
    try {
        resolve_actuator("nonesuch");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("no actuator named 'nonesuch' (known: "),
                  std::string::npos);
        EXPECT_NE(std::string(e.what()).find("lra-175"), std::string::npos);
    }
    EXPECT_THROW(resolve_actuator((dir_ / "missing.toml").string()), std::runtime_error);
}

}  // namespace
}  // namespace tactus
