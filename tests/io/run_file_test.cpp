// run_file: streams a file through an Engine in blocks; the output equals processing the whole
// file in one go, every frame reaches on_output, progress ends at the total, a file at an
// unsupported rate or without frames is rejected naming the file.
#include "tactus/io/run_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/signals.hpp"
#include "support/temp_dir.hpp"
#include "tactus/io/audio_writer.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class RunFileTest : public test::TempDirTest {
  protected:
    fs::path write(const std::string& name, const std::vector<float>& x, double fs) {
        const fs::path path = dir_ / name;
        AudioWriter writer(path, fs, 1);
        if (!x.empty()) writer.write(x.data(), static_cast<int>(x.size()));
        writer.commit();
        return path;
    }
};

TEST_F(RunFileTest, OutputMatchesTheEngineAndProgressReachesTheEnd) {
    const double fs = 44100;
    const test::DrumSignal drums = test::drum_pattern(fs, 2.5, 9);
    const fs::path path = write("drums.wav", drums.audio, fs);

    Engine engine;
    std::vector<float> streamed;
    int64_t last_done = -1, last_total = -1;
    int reports = 0;
    const RunSummary summary =
        run_file(path, engine,
                 {[&](const float* v, int n) { streamed.insert(streamed.end(), v, v + n); },
                  [&](int64_t done, int64_t total) {
                      EXPECT_GE(done, last_done);
                      last_done = done, last_total = total;
                      ++reports;
                  }});
    EXPECT_EQ(summary.sample_rate_hz, fs);
    EXPECT_EQ(summary.input_channels, 1);
    EXPECT_EQ(summary.frames, static_cast<int64_t>(drums.audio.size()));
    EXPECT_EQ(last_done, summary.frames);
    EXPECT_EQ(last_total, summary.frames);
    EXPECT_GE(reports, 2);

    Engine direct;
    direct.prepare(fs, Engine::kMaxBlock);
    std::vector<float> expected(drums.audio.size());
    for (size_t done = 0; done < expected.size(); done += Engine::kMaxBlock) {
        const int n = static_cast<int>(std::min<size_t>(Engine::kMaxBlock, expected.size() - done));
        direct.process(drums.audio.data() + done, expected.data() + done, n);
    }
    EXPECT_EQ(streamed, expected);
}

TEST_F(RunFileTest, RejectsUnsupportedRatesNamingTheFile) {
    const fs::path path = write("slow.wav", std::vector<float>(4000, 0.1f), 4000);
    Engine engine;
    try {
        run_file(path, engine);
        ADD_FAILURE() << "accepted a 4 kHz file";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr(path.string()));
        EXPECT_THAT(e.what(), HasSubstr("4000"));
    }
}

TEST_F(RunFileTest, RejectsEmptyFiles) {
    const fs::path path = write("empty.wav", {}, 48000);
    Engine engine;
    try {
        run_file(path, engine);
        ADD_FAILURE() << "accepted an empty file";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr(path.string()));
        EXPECT_THAT(e.what(), HasSubstr("no audio frames"));
    }
}

}  // namespace
}  // namespace tactus
