// Presets and --set: apply_assignment rejects malformed assignments, unknown keys (suggesting
// the nearest key), bad values (naming key and range); apply_preset_text reports TOML syntax
// errors as origin:line:column, unknown keys with a suggestion, wrong types, and applies all or
// nothing; the shipped presets/tfd.toml loads and every value in it arrives in the Settings;
// the preset search path, listing and name resolution.
#include "tactus/io/preset.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "tactus/io/search_path.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path kSourceDir = TACTUS_SOURCE_DIR;

template <typename Exception>
std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Exception& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("(wrong exception type) ") + e.what();
    }
    return "(no exception)";
}

std::string text_error(const std::string& toml) {
    Settings s;
    return message_of<std::runtime_error>([&] { apply_preset_text(s, toml, "test.toml"); });
}

TEST(ApplyAssignment, SetsValuesAndChoices) {
    Settings s;
    apply_assignment(s, "envelope.decay_ms=120");
    EXPECT_EQ(s[P::envelope_decay_ms], 120.0);
    apply_assignment(s, "mapping.frequency.curve=lin");
    EXPECT_EQ(s[P::frequency_curve], static_cast<double>(MappingCurve::lin));
    apply_assignment(s, "post.drive_db=-3.5");
    EXPECT_EQ(s[P::post_drive_db], -3.5);
}

TEST(ApplyAssignment, RejectsMalformedInput) {
    for (const char* bad :
         {"", "envelope.decay_ms", "=120", "envelope.decay_ms=", "=", "envelope.decay_ms 120"}) {
        Settings s;
        const std::string m = message_of<std::invalid_argument>([&] { apply_assignment(s, bad); });
        EXPECT_THAT(m, HasSubstr("expected key=value")) << "'" << bad << "': " << m;
    }
}

TEST(ApplyAssignment, UnknownKeySuggestsTheNearest) {
    Settings s;
    const std::string m =
        message_of<std::invalid_argument>([&] { apply_assignment(s, "envelope.decay=120"); });
    EXPECT_THAT(m, HasSubstr("unknown key 'envelope.decay'"));
    EXPECT_THAT(m, HasSubstr("did you mean 'envelope.decay_ms'"));
}

TEST(ApplyAssignment, BadValuesNameTheKey) {
    Settings s;
    std::string m =
        message_of<std::invalid_argument>([&] { apply_assignment(s, "envelope.decay_ms=9999"); });
    EXPECT_THAT(m, HasSubstr("envelope.decay_ms"));
    EXPECT_THAT(m, HasSubstr("5 to 5000"));
    m = message_of<std::invalid_argument>([&] { apply_assignment(s, "envelope.decay_ms=fast"); });
    EXPECT_THAT(m, HasSubstr("envelope.decay_ms"));
    EXPECT_THAT(m, HasSubstr("not a number"));
    m = message_of<std::invalid_argument>(
        [&] { apply_assignment(s, "mapping.amplitude.source=volume"); });
    EXPECT_THAT(m, HasSubstr("mapping.amplitude.source"));
    EXPECT_THAT(m, HasSubstr("loudness_db"));
    EXPECT_EQ(s[P::envelope_decay_ms], Settings{}[P::envelope_decay_ms]);
}

TEST(ApplyPresetText, AppliesTablesAndDottedKeys) {
    Settings s;
    apply_preset_text(s,
                      "description = \"test\"\nname = \"t\"\npost.drive_db = 6\n"
                      "[envelope]\ndecay_ms = 90\n"
                      "[mapping.frequency]\ncurve = \"exp\"\nout_max = 250\n",
                      "test.toml");
    EXPECT_EQ(s[P::envelope_decay_ms], 90.0);
    EXPECT_EQ(s[P::frequency_curve], static_cast<double>(MappingCurve::exp));
    EXPECT_EQ(s[P::frequency_out_max], 250.0);
    EXPECT_EQ(s[P::post_drive_db], 6.0);
}

TEST(ApplyPresetText, DottedKeyInsideATableIsUnknown) {
    // Under [mapping.frequency], "post.drive_db" means mapping.frequency.post.drive_db.
    const std::string m = text_error("[mapping.frequency]\npost.drive_db = 6\n");
    EXPECT_THAT(m, HasSubstr("unknown key 'mapping.frequency.post.drive_db'"));
}

TEST(ApplyPresetText, SyntaxErrorsGiveLineAndColumn) {
    std::string m = text_error("[envelope]\ndecay_ms = = 3\n");
    EXPECT_THAT(m, StartsWith("test.toml:2:"));
    EXPECT_THAT(m, HasSubstr("TOML syntax error"));
    m = text_error("description = \"x\"\n\n\n[post\nband_low_hz = 20\n");
    EXPECT_THAT(m, StartsWith("test.toml:4:"));
    m = text_error("[envelope]\ndecay_ms = 3\ndecay_ms = 4\n");  // redefinition
    EXPECT_THAT(m, StartsWith("test.toml:3:"));
    // Column: the offending character on the line.
    m = text_error("[envelope]\ndecay_ms = 12x\n");
    EXPECT_THAT(m, HasSubstr("test.toml:2:"));
    const size_t colon = m.find(':', std::string("test.toml:2").size());
    ASSERT_NE(colon, std::string::npos);
    EXPECT_GT(std::atoi(m.c_str() + colon + 1), 1) << m;
}

TEST(ApplyPresetText, UnknownKeysSuggestAndGiveTheLine) {
    const std::string m = text_error("[envelope]\nattack_ms = 2\ndecay = 100\n");
    EXPECT_THAT(m, StartsWith("test.toml:3:"));
    EXPECT_THAT(m, HasSubstr("unknown key 'envelope.decay'"));
    EXPECT_THAT(m, HasSubstr("did you mean 'envelope.decay_ms'"));
}

TEST(ApplyPresetText, WrongTypes) {
    std::string m = text_error("[envelope]\ndecay_ms = \"slow\"\n");
    EXPECT_THAT(m, StartsWith("test.toml:2:"));
    EXPECT_THAT(m, HasSubstr("envelope.decay_ms must be a number"));
    m = text_error("[envelope]\ndecay_ms = true\n");
    EXPECT_THAT(m, HasSubstr("envelope.decay_ms must be a number"));
    m = text_error("[envelope]\ndecay_ms = [1, 2]\n");
    EXPECT_THAT(m, HasSubstr("envelope.decay_ms must be a number"));
    m = text_error("[mapping.amplitude]\nsource = 2\n");
    EXPECT_THAT(m, HasSubstr("mapping.amplitude.source must be a name in quotes"));
    m = text_error("[mapping.amplitude]\ncurve = \"cubic\"\n");
    EXPECT_THAT(m, HasSubstr("'cubic' is not one of: lin, log, exp"));
    m = text_error("description = 3\n");
    EXPECT_THAT(m, HasSubstr("'description' must be a string"));
    m = text_error("[post]\nceiling_db = 3\n");
    EXPECT_THAT(m, StartsWith("test.toml:2:"));
    EXPECT_THAT(m, HasSubstr("post.ceiling_db = 3 is out of range: allowed -40 to 0 dB"));
}

TEST(ApplyPresetText, IntegersAreNumbers) {
    Settings s;
    apply_preset_text(s, "[envelope]\ndecay_ms = 200\n[post]\ndrive_db = -6\n", "t");
    EXPECT_EQ(s[P::envelope_decay_ms], 200.0);
    EXPECT_EQ(s[P::post_drive_db], -6.0);
}

TEST(ApplyPresetText, AllOrNothing) {
    Settings s;
    s.set(P::envelope_attack_ms, 7);
    EXPECT_THROW(apply_preset_text(s, "[envelope]\nattack_ms = 3\ndecay_ms = 1e9\n", "t"),
                 std::runtime_error);
    EXPECT_EQ(s[P::envelope_attack_ms], 7.0);
    EXPECT_EQ(s[P::envelope_decay_ms], Settings{}[P::envelope_decay_ms]);
}

// Walks a TOML table and checks every value against the Settings it was loaded into.
void expect_loaded(const Settings& s, const toml::table& table, const std::string& prefix) {
    for (const auto& [name, node] : table) {
        const std::string key =
            prefix.empty() ? std::string(name.str()) : prefix + "." + std::string(name.str());
        if (const auto* child = node.as_table()) {
            expect_loaded(s, *child, key);
            continue;
        }
        if (key == "description" || key == "name") continue;
        const auto id = find_param(key);
        ASSERT_TRUE(id.has_value()) << key;
        if (!spec(*id).choices.empty()) {
            EXPECT_EQ(s.text_of(*id), node.value<std::string>().value_or("?")) << key;
        } else {
            EXPECT_EQ(s[*id], node.value<double>().value_or(-1e300)) << key;
        }
    }
}

TEST(Presets, ShippedTfdLoads) {
    const fs::path path = kSourceDir / "presets" / "tfd.toml";
    ASSERT_TRUE(fs::is_regular_file(path)) << path;
    Settings s;
    ASSERT_NO_THROW(apply_preset_file(s, path));
    expect_loaded(s, toml::parse_file(path.string()), "");
    for (size_t i = 0; i < param_table().size(); ++i) {
        EXPECT_GE(s[static_cast<P>(i)], param_table()[i].min) << param_table()[i].key;
        EXPECT_LE(s[static_cast<P>(i)], param_table()[i].max) << param_table()[i].key;
    }
}

// four-channel: loads completely, and its P carrier and post chain are tfd's (only the further
// channels differ, so the two presets compare the channel components alone).
TEST(Presets, ShippedFourChannelLoadsAndKeepsTheTfdCarrier) {
    const fs::path path = kSourceDir / "presets" / "four-channel.toml";
    Settings four, tfd;
    ASSERT_NO_THROW(apply_preset_file(four, path));
    expect_loaded(four, toml::parse_file(path.string()), "");
    apply_preset_file(tfd, kSourceDir / "presets" / "tfd.toml");
    EXPECT_GT(four[P::flutter_weight], 0.0);
    EXPECT_GT(four[P::pressure_weight], 0.0);
    for (size_t i = 0; i < param_table().size(); ++i) {
        const std::string_view key = param_table()[i].key;
        const bool channel_setting = key.starts_with("flutter.") || key.starts_with("pressure.") ||
                                     key.starts_with("mapping.flutter") ||
                                     key.starts_with("mapping.pressure") ||
                                     key.starts_with("post.flutter") || key == "actuator.dc";
        if (!channel_setting) {
            EXPECT_EQ(four[static_cast<P>(i)], tfd[static_cast<P>(i)]) << key;
        }
    }
}

TEST(Presets, EveryShippedPresetLoads) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(kSourceDir / "presets")) {
        if (entry.path().extension() != ".toml") continue;
        Settings s;
        EXPECT_NO_THROW(apply_preset_file(s, entry.path())) << entry.path();
        ++count;
    }
    EXPECT_GE(count, 1);
}

class TemporaryDirectory {
  public:
    TemporaryDirectory() {
        std::string pattern = (fs::temp_directory_path() / "tactus-test-XXXXXX").string();
        path_ = ::mkdtemp(pattern.data());
    }
    ~TemporaryDirectory() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

void write_file(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
}

TEST(Presets, FileErrorsNameTheFile) {
    TemporaryDirectory dir;
    Settings s;
    const fs::path missing = dir.path() / "missing.toml";
    std::string m = message_of<std::runtime_error>([&] { apply_preset_file(s, missing); });
    EXPECT_THAT(m, HasSubstr("preset file '" + missing.string() + "' not found"));

    const fs::path broken = dir.path() / "broken.toml";
    write_file(broken, "[envelope]\ndecay_ms = \n");
    m = message_of<std::runtime_error>([&] { apply_preset_file(s, broken); });
    EXPECT_THAT(m, StartsWith(broken.string() + ":2:"));
    EXPECT_THAT(m, HasSubstr("TOML syntax error"));

    const fs::path unknown = dir.path() / "unknown.toml";
    write_file(unknown, "\n[post]\nband_lo_hz = 30\n");
    m = message_of<std::runtime_error>([&] { apply_preset_file(s, unknown); });
    EXPECT_THAT(m, StartsWith(unknown.string() + ":3:"));
    EXPECT_THAT(m, HasSubstr("did you mean 'post.band_low_hz'"));
}

class PresetPathEnvironment : public ::testing::Test {
  protected:
    void SetUp() override {
        for (const char* name : kNames)
            if (const char* old = std::getenv(name)) saved_[name] = old;
    }
    void TearDown() override {
        for (const char* name : kNames)
            if (saved_.count(name))
                ::setenv(name, saved_[name].c_str(), 1);
            else
                ::unsetenv(name);
    }
    static constexpr const char* kNames[] = {"TACTUS_PRESET_PATH", "XDG_DATA_HOME"};
    std::map<std::string, std::string> saved_;
};

TEST_F(PresetPathEnvironment, SearchPathListingAndResolution) {
    TemporaryDirectory a, b;
    write_file(a.path() / "mine.toml", "description = \"first\"\n");
    write_file(b.path() / "mine.toml", "description = \"shadowed\"\n");
    write_file(b.path() / "tfd.toml", "description = \"user tfd\"\n");
    write_file(b.path() / "bad.toml", "description = \n");
    write_file(b.path() / "notes.txt", "not a preset\n");
    const std::string value = a.path().string() + "::" + b.path().string() + ":";
    ::setenv("TACTUS_PRESET_PATH", value.c_str(), 1);
    TemporaryDirectory data_home;
    ::setenv("XDG_DATA_HOME", data_home.path().c_str(), 1);

    // The variable's directories, the user's data directory, then the data beside the program.
    const auto dirs = preset_search_path();
    ASSERT_EQ(dirs.size(), 4u);
    EXPECT_EQ(dirs[0], a.path());
    EXPECT_EQ(dirs[1], b.path());
    EXPECT_EQ(dirs[2], data_home.path() / "tactus" / "presets");
    EXPECT_EQ(dirs[3], installed_data_dir() / "presets");
    fs::create_directories(dirs[2]);
    write_file(dirs[2] / "mine.toml", "description = \"hidden by the variable\"\n");
    write_file(dirs[2] / "home.toml", "description = \"user data\"\n");
    EXPECT_EQ(resolve_preset("home"), dirs[2] / "home.toml");

    const auto presets = list_presets();
    std::map<std::string, PresetInfo> by_name;
    for (const auto& p : presets) by_name[p.name] = p;
    EXPECT_TRUE(std::is_sorted(presets.begin(), presets.end(),
                               [](const auto& x, const auto& y) { return x.name < y.name; }));
    ASSERT_TRUE(by_name.count("mine"));
    EXPECT_EQ(by_name["mine"].description, "first");
    EXPECT_EQ(by_name["mine"].path, a.path() / "mine.toml");
    ASSERT_TRUE(by_name.count("tfd"));
    EXPECT_EQ(by_name["tfd"].description, "user tfd");  // earlier directories shadow later ones
    EXPECT_EQ(by_name["bad"].description, "(does not parse)");
    EXPECT_FALSE(by_name.count("notes"));

    EXPECT_EQ(resolve_preset("mine"), a.path() / "mine.toml");
    EXPECT_EQ(resolve_preset("tfd"), b.path() / "tfd.toml");
    EXPECT_EQ(resolve_preset((b.path() / "mine.toml").string()), b.path() / "mine.toml");
    const std::string m = message_of<std::runtime_error>([] { resolve_preset("nothing"); });
    EXPECT_THAT(m, HasSubstr("no preset named 'nothing'"));
    EXPECT_THAT(m, HasSubstr("mine"));
    EXPECT_THAT(message_of<std::runtime_error>([] { resolve_preset("nowhere/x.toml"); }),
                HasSubstr("preset file 'nowhere/x.toml' not found"));
}

TEST_F(PresetPathEnvironment, ShippedPresetsAreFoundByName) {
    ::unsetenv("TACTUS_PRESET_PATH");
    const fs::path tfd = resolve_preset("tfd");
    EXPECT_TRUE(fs::equivalent(tfd, kSourceDir / "presets" / "tfd.toml")) << tfd;
}

TEST(ApplyAssignment, ControlCharactersAreEscapedSoTheMessageIsOneLine) {
    Settings s;
    try {
        apply_assignment(s, "a\nb\x01=1");
        ADD_FAILURE() << "accepted an unknown key";
    } catch (const std::invalid_argument& e) {
        EXPECT_THAT(e.what(), HasSubstr("unknown key 'a\\nb\\x01'"));
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
    try {
        apply_assignment(s, "envelope.decay_ms=1\t2");
        ADD_FAILURE() << "accepted a tab in a number";
    } catch (const std::invalid_argument& e) {
        EXPECT_THAT(e.what(), HasSubstr("'1\\t2' is not a number"));
    }
}

TEST(ApplyAssignment, AHugeKeyIsAnsweredQuickly) {
    Settings s;
    const std::string key(1 << 20, 'x');  // edit distance on a megabyte would take minutes
    EXPECT_THROW(apply_assignment(s, key + "=1"), std::invalid_argument);
}

}  // namespace
}  // namespace tactus
