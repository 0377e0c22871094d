// Layouts on the command line (io/layout_file.hpp): render --layout writes each output on its
// channel and the sound on the sound channels; meter reads the layout back from the file and
// meters each output through its own actuator; a bad layout is one line naming the file, the
// line and the key, and nothing is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/signals.hpp"
#include "support/sounds.hpp"
#include "tactus/io/audio_reader.hpp"

namespace {

namespace fs = std::filesystem;
using tactus::test::Cli;
using tactus::test::kAmen;

// Every channel of a sound file, whole.
std::vector<std::vector<float>> channels_of(const fs::path& path) {
    tactus::AudioReader reader(path);
    std::vector<std::vector<float>> channels(static_cast<size_t>(reader.channels()));
    tactus::ChannelBlock block(reader.channels(), 4096);
    while (const int n = reader.read(block.data(), 4096))
        for (size_t c = 0; c < channels.size(); ++c)
            channels[c].insert(channels[c].end(), block[static_cast<int>(c)],
                               block[static_cast<int>(c)] + n);
    return channels;
}

TEST_F(Cli, RenderWithALayoutPutsEachOutputOnItsChannelAndTheSoundOnItsOwn) {
    const fs::path out = dir_ / "controller.wav", left = dir_ / "left.wav";
    auto r = run("render " + kAmen + " -o " + out.string() + " --layout controller");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto written = channels_of(out);
    ASSERT_EQ(written.size(), 4u) << "sound on 1-2, haptics on 3-4";
    const auto input = channels_of(kAmen);
    for (size_t c = 0; c < 2; ++c) {
        std::vector<float> sound(written[c].begin(),
                                 written[c].begin() + static_cast<long>(input[c].size()));
        EXPECT_TRUE(tactus::test::same_bits(sound, input[c])) << "sound channel " << c + 1;
    }
    std::ofstream(dir_ / "left.toml") << "[[output]]\nroute = \"channel:1\"\nactuator = "
                                         "\"voice-coil\"\n";
    r = run("render " + kAmen + " -o " + left.string() + " --layout " +
            (dir_ / "left.toml").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto alone = channels_of(left);
    ASSERT_EQ(alone.size(), 1u);
    EXPECT_TRUE(tactus::test::same_bits(written[2], alone[0])) << "the left output, as alone";
    EXPECT_GT(tactus::test::peak(written[3]), 0.05);
}

TEST_F(Cli, MeterOfALayoutsRenderMetersEachOutputThroughItsActuator) {
    const fs::path out = dir_ / "wrists.wav", csv = dir_ / "wrists.csv";
    ASSERT_EQ(run("render " + kAmen + " -o " + out.string() + " --layout wrists").exit_code, 0);
    const auto r = run("meter " + out.string() + " -o " + csv.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* expected :
         {"output left (channel 1): ", "output right (channel 2): ", "through lra-175"})
        EXPECT_NE(r.out.find(expected), std::string::npos) << expected << "\n" << r.out;
    std::ifstream f(csv);
    std::string header;
    std::getline(f, header);
    EXPECT_EQ(header,
              "time_s,left_P_sl_db,left_NPI_sl_db,left_NPII_sl_db,left_NPIII_sl_db,"
              "left_combined_sl_db,right_P_sl_db,right_NPI_sl_db,right_NPII_sl_db,"
              "right_NPIII_sl_db,right_combined_sl_db");
}

TEST_F(Cli, ABadLayoutNamesTheFileLineAndKeyAndWritesNothing) {
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"[[output]]\nroute = \"kicks\"\n", ":2:9: output[1].route: route 'kicks'"},
        {"[[output]]\nname = \"a\"\n[[output]]\nname = \"a\"\n",
         "output[2].name: 'a' names an earlier output too"},
        {"sound = [1]\n[[output]]\nchannel = 1\n", "output[1].channel: channel 1 is taken"},
        {"[[output]]\nroute = \"all\"\nrotue = \"kick\"\n", ":3:9: output[1].rotue: unknown key"},
        {"description = \"none\"\n", "output: a layout needs one [[output]] table"},
        {"[[output]]\n[output.set]\npost.ceiling_db = -6\n",
         "post.ceiling_db: an output may set only the mapping's live parameters"},
        {"[[output]]\nname = \"a b\"\n", "output[1].name: 1-64 letters"},
        {"[[output]]\nactuator = \"no-such\"\n", "output output1: no actuator named 'no-such'"},
        {"[[output]]\ngain_db = 3\n", "output[1].gain_db: 3 is out of range"},
    };
    for (const auto& [text, expected] : bad) {
        std::ofstream(dir_ / "bad.toml") << text;
        const fs::path out = dir_ / "out.wav";
        const auto r = run("render " + kAmen + " -o " + out.string() + " --layout " +
                           (dir_ / "bad.toml").string());
        EXPECT_NE(r.exit_code, 0) << text;
        EXPECT_NE(r.err.find(expected), std::string::npos) << text << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(fs::exists(out)) << text;
    }
}

}  // namespace
