// The live and studio commands run by their helper programs (apps/tactus/helper_programs.hpp):
// every other command loads none of their libraries (seen by the dynamic loader itself,
// LD_DEBUG=libs), the helpers' commands answer through `tactus` as before, and a helper that is
// missing is one line naming it.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/run_cli.hpp"
#include "support/sound_file.hpp"

namespace {

namespace fs = std::filesystem;
using Result = tactus::test::CliResult;

// The live front end's and the studio's libraries, and what they bring (PulseAudio, OpenSSL).
const char* const kHelperLibraries[] = {"librtaudio", "libjack", "libasound", "liblo.",
                                        "libpulse",   "libssl",  "libcrypto", "libbrotli"};

class HelperPrograms : public tactus::test::Cli {};

TEST_F(HelperPrograms, OtherCommandsLoadNoneOfTheirLibraries) {
    const fs::path in = dir_ / "click.wav", out = dir_ / "click.vibration.wav";
    tactus::test::write_sound_file(in, std::vector<float>(480, 0.5f), 48000);
    for (const std::string& command :
         {"render " + in.string() + " -o " + out.string(), std::string("--version"),
          std::string("presets"), std::string("--help")}) {
        const Result r = run(command, "LD_DEBUG=libs ");
        ASSERT_EQ(r.exit_code, 0) << command << '\n' << r.err;
        ASSERT_NE(r.err.find("libsndfile"), std::string::npos) << "no loader messages";
        for (const char* library : kHelperLibraries)
            EXPECT_EQ(r.err.find(library), std::string::npos) << command << " loads " << library;
    }
}

TEST_F(HelperPrograms, TheirCommandsAnswerThroughTactus) {
#ifndef TACTUS_LIVE
    GTEST_SKIP() << "the live front end is not built";
#else
    Result r = run("-q devices", "LD_DEBUG=libs ");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("jack (Jack)"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("librtaudio"), std::string::npos);
    for (const char* command : {"live", "calibrate"}) {
        r = run(std::string(command) + " --help");
        EXPECT_EQ(r.exit_code, 0) << command;
        EXPECT_NE(r.out.find("Usage: " TACTUS_CLI " " + std::string(command)), std::string::npos)
            << r.out;
        EXPECT_NE(r.out.find("--backend"), std::string::npos) << r.out;
    }
    // The helper finds the presets installed beside `tactus`, as `tactus` does.
    r = run("live --preset nosuch", "env -i HOME=" + dir_.string() + " ");
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("no preset named 'nosuch' (known: drums, four-channel"), std::string::npos)
        << r.err;
#endif
#ifdef TACTUS_STUDIO
    r = run("studio --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("--no-browser"), std::string::npos) << r.out;
#endif
}

TEST_F(HelperPrograms, AMissingHelperIsOneLineNamingIt) {
#ifndef TACTUS_LIVE
    GTEST_SKIP() << "the live front end is not built";
#else
    const fs::path copy = dir_ / "bin" / "tactus";  // no libexec/tactus beside it
    fs::create_directories(copy.parent_path());
    fs::copy_file(TACTUS_CLI, copy);
    const Result r = run("devices", "", copy);
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "tactus: error: `tactus devices` needs its program '" +
                         (dir_ / "libexec" / "tactus" / "tactus-live").string() +
                         "': No such file or directory\n");
    EXPECT_EQ(r.out, "");
#endif
}

}  // namespace
