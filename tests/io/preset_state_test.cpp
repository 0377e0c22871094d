// Settings as preset text (the engine's state for a plugin session or a patch): every
// parameter written, read back bit for bit (the shipped presets and random settings), a
// format version that refuses newer files, and renamed keys that still load from older ones.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cstring>
#include <random>
#include <stdexcept>
#include <string>

#include "tactus/io/preset.hpp"

namespace tactus {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

bool bit_identical(const Settings& a, const Settings& b) {
    for (const ParamSpec& s : param_table()) {
        const double x = a[s.param], y = b[s.param];
        if (std::memcmp(&x, &y, sizeof x) != 0) {
            ADD_FAILURE() << s.key << ": " << x << " read back as " << y;
            return false;
        }
    }
    return true;
}

Settings shipped(const char* name) {
    Settings s;
    apply_preset_file(s, resolve_preset(name));
    return s;
}

// Any value each parameter allows: uniform over its range, whole for whole-number types, and
// sometimes a bound or a value with a long decimal expansion.
Settings random_settings(std::mt19937_64& random) {
    Settings s;
    for (const ParamSpec& p : param_table()) {
        std::uniform_real_distribution<double> within(p.min, p.max);
        double v = within(random);
        switch (random() % 8) {
            case 0:
                v = p.min;
                break;
            case 1:
                v = p.max;
                break;
            case 2:
                v = std::nextafter(v, p.max);
                break;
            default:
                break;
        }
        s.set(p.param, v);
    }
    return s;
}

void expect_round_trip(const Settings& settings) {
    const std::string text = preset_text(settings, "round trip");
    Settings onto_defaults, onto_other = shipped("four-channel");
    apply_preset_text(onto_defaults, text, "state.toml");
    apply_preset_text(onto_other, text, "state.toml");
    EXPECT_TRUE(bit_identical(onto_defaults, settings)) << text;
    EXPECT_TRUE(bit_identical(onto_other, settings)) << text;
}

TEST(PresetState, ShippedPresetsReadBackBitForBit) {
    expect_round_trip(Settings{});
    expect_round_trip(shipped("tfd"));
    expect_round_trip(shipped("four-channel"));
}

TEST(PresetState, RandomSettingsReadBackBitForBit) {
    std::mt19937_64 random(11);
    for (int i = 0; i < 200; ++i) expect_round_trip(random_settings(random));
}

TEST(PresetState, NegativeZeroStaysNegative) {
    Settings s;
    s.set(P::post_drive_db, -0.0);
    expect_round_trip(s);
}

TEST(PresetState, EveryParameterIsWrittenOnceWithTheFormat) {
    const std::string text = preset_text(Settings{}, "say \"hi\"\nthere");
    const toml::table table = toml::parse(text);
    EXPECT_EQ(table["format"].value<int64_t>(), kPresetFormat);
    EXPECT_EQ(table["description"].value<std::string>(), "say \"hi\"\nthere");
    for (const ParamSpec& s : param_table())
        EXPECT_TRUE(table.at_path(s.key).node() != nullptr) << s.key;
    for (const char* group : {"\n[analysis]\n", "\n[envelope]\n", "\n[mapping]\n", "\n[post]\n"}) {
        const size_t first = text.find(group);
        EXPECT_NE(first, std::string::npos) << group;
        EXPECT_EQ(text.find(group, first + 1), std::string::npos) << group << " twice";
    }
}

TEST(PresetState, ANewerFormatIsRefusedWithItsLine) {
    Settings s;
    for (const char* bad : {"format = 99\n", "format = 0\n", "format = \"1\"\n"}) {
        try {
            apply_preset_text(s, std::string("description = \"x\"\n") + bad, "new.toml");
            ADD_FAILURE() << bad;
        } catch (const std::runtime_error& e) {
            EXPECT_THAT(e.what(), StartsWith("new.toml:2:")) << bad;
            EXPECT_THAT(e.what(), HasSubstr("format")) << bad;
        }
    }
    try {
        apply_preset_text(s, "format = 2\n", "new.toml");
        ADD_FAILURE();
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr("format 2 is newer than this tactus reads (1)"));
    }
    apply_preset_text(s, "format = 1\n[envelope]\ndecay_ms = 90\n", "current.toml");
    EXPECT_EQ(s[P::envelope_decay_ms], 90.0);
}

TEST(PresetState, RenamedKeysLoadFromOlderFormats) {
    // Two renames of one key, in formats 2 and 3.
    constexpr KeyRename renames[] = {{2, "envelope.decay", "envelope.release"},
                                     {3, "envelope.release", "envelope.decay_ms"}};
    EXPECT_EQ(current_key("envelope.decay", 1, renames), "envelope.decay_ms");
    EXPECT_EQ(current_key("envelope.release", 2, renames), "envelope.decay_ms");
    EXPECT_EQ(current_key("envelope.release", 3, renames), "envelope.release");
    EXPECT_EQ(current_key("post.drive_db", 1, renames), "post.drive_db");
    for (const KeyRename& r : kKeyRenames) {  // every shipped rename leads to a known key
        EXPECT_LE(r.since, kPresetFormat);
        EXPECT_TRUE(find_param(current_key(r.old_key, r.since - 1)).has_value()) << r.old_key;
    }
}

}  // namespace
}  // namespace tactus
