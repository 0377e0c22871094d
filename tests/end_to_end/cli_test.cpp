// The tactus command line, run as a user runs it: outputs on real files, exit codes, one-line
// errors on stderr, and nothing written (or overwritten) when a run fails.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/run_cli.hpp"

namespace {

namespace fs = std::filesystem;
const std::string kAmen = "/usr/share/sonic-pi/samples/loop_amen_full.flac";

using tactus::test::Cli;
using tactus::test::info_of;
using Result = tactus::test::CliResult;

TEST_F(Cli, HelpEverywhere) {
    for (const char* command : {"", "render ", "analyze ", "onsets ", "presets "}) {
        const Result r = run(std::string(command) + "--help");
        EXPECT_EQ(r.exit_code, 0) << command;
        EXPECT_NE(r.out.find("Usage"), std::string::npos) << command;
    }
}

TEST_F(Cli, PresetsListsTfdAndParameters) {
    EXPECT_NE(run("presets").out.find("tfd"), std::string::npos);
    const Result params = run("presets --params");
    EXPECT_NE(params.out.find("envelope.decay_ms"), std::string::npos);
}

TEST_F(Cli, RenderWritesFloatWavWithChannelsAtInputRate) {
    const fs::path out = dir_ / "amen.vibration.wav";
    const Result r = run("render " + kAmen + " -o " + out.string() + " --channels 3");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const SF_INFO in = info_of(kAmen), written = info_of(out);
    EXPECT_EQ(written.samplerate, in.samplerate);
    EXPECT_EQ(written.frames, in.frames);
    EXPECT_EQ(written.channels, 3);
    EXPECT_EQ(written.format & SF_FORMAT_SUBMASK, SF_FORMAT_FLOAT);
    EXPECT_TRUE(r.out.empty()) << "messages belong on stderr";
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos);
}

TEST_F(Cli, AnalyzeCsvAndJson) {
    const Result csv = run("analyze " + kAmen);
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    EXPECT_EQ(csv.out.rfind("time_s,loudness_db,brightness_hz,noisiness,pitch_hz", 0), 0u);
    const auto rows = std::count(csv.out.begin(), csv.out.end(), '\n') - 1;
    const double seconds = static_cast<double>(info_of(kAmen).frames) / info_of(kAmen).samplerate;
    EXPECT_NEAR(rows, seconds / 0.0029, 0.02 * rows);  // one row per 2.9 ms frame

    const fs::path json = dir_ / "amen.json";
    ASSERT_EQ(run("analyze " + kAmen + " -o " + json.string()).exit_code, 0);
    std::ifstream f(json);
    std::string text((std::istreambuf_iterator<char>(f)), {});
    EXPECT_EQ(text.front(), '[');
    EXPECT_NE(text.find("\"frequency_hz\""), std::string::npos);
    EXPECT_EQ(text.substr(text.size() - 2), "]\n");
}

TEST_F(Cli, OnsetsAreAscendingTriples) {
    const Result r = run("onsets " + kAmen);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream lines(r.out);
    double onset, decided, strength, previous = -1;
    int count = 0;
    while (lines >> onset >> decided >> strength) {
        EXPECT_GE(onset, previous);
        EXPECT_GE(decided, onset);
        EXPECT_LT(decided - onset, 0.05);
        previous = onset;
        ++count;
    }
    EXPECT_GT(count, 20);
}

TEST_F(Cli, BadInputFailsCleanlyAndWritesNothing) {
    const fs::path out = dir_ / "out.wav";
    const fs::path text = dir_ / "notes.wav";
    std::ofstream(text) << "not audio\n";

    const Result not_audio = run("render " + text.string() + " -o " + out.string());
    EXPECT_NE(not_audio.exit_code, 0);
    EXPECT_NE(not_audio.err.find(text.string()), std::string::npos) << not_audio.err;
    EXPECT_FALSE(fs::exists(out));

    const Result unknown_key =
        run("render " + kAmen + " -o " + out.string() + " --set envelope.decay=100");
    EXPECT_NE(unknown_key.exit_code, 0);
    EXPECT_NE(unknown_key.err.find("did you mean 'envelope.decay_ms'"), std::string::npos)
        << unknown_key.err;
    EXPECT_FALSE(fs::exists(out));

    const Result out_of_range =
        run("render " + kAmen + " -o " + out.string() + " --set envelope.decay_ms=-3");
    EXPECT_NE(out_of_range.exit_code, 0);
    EXPECT_NE(out_of_range.err.find("allowed"), std::string::npos) << out_of_range.err;

    EXPECT_NE(run("render " + kAmen + " -o " + out.string() + " --preset nonesuch").exit_code, 0);
    EXPECT_NE(run("render /no/such/file.wav -o " + out.string()).exit_code, 0);
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, NeverOverwritesTheInput) {
    const fs::path input = dir_ / "in.flac";
    fs::copy_file(kAmen, input);
    const auto size = fs::file_size(input);
    const Result r = run("render " + input.string() + " -o " + input.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("overwrite the input"), std::string::npos) << r.err;
    EXPECT_EQ(fs::file_size(input), size);
}

}  // namespace
