// run_file: streams a file through an Engine in blocks; the output equals processing the whole
// file in one go, every frame reaches on_output, progress ends at the total, a file at an
// unsupported rate or without frames is rejected naming the file. analyse_file gives the
// engine's features, and only the onsets when asked for none. Audio in memory runs as the file.
#include "tactus/io/run_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/engine_blocks.hpp"
#include "support/signals.hpp"
#include "support/sound_file.hpp"
#include "support/temp_dir.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class RunFileTest : public test::TempDirTest {
  protected:
    // A mono float WAV in the test's directory.
    fs::path write(const std::string& name, const std::vector<float>& x, double fs) {
        const fs::path path = dir_ / name;
        test::write_sound_file(path, x, fs);
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
    const RunSummary summary = run_file(
        path, engine,
        {[&](const float* const* v, int n) { streamed.insert(streamed.end(), v[0], v[0] + n); },
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
    const std::vector<float> expected =
        test::process_in_blocks(direct, drums.audio, Engine::kMaxBlock);
    EXPECT_EQ(streamed, expected);
}

class FeatureList final : public FrameObserver {
  public:
    void on_frame(const Features& f, const ControlFrame&) noexcept override { frames.push_back(f); }
    std::vector<Features> frames;
};

// a holds b's frames, then analyse_file's silence (BlockAnalysis::finish: parts.settle_ms and a
// hop), which decides the last onset's part.
void expect_same_features(const std::vector<Features>& a, const std::vector<Features>& b) {
    const Settings defaults;
    const auto padding_frames = static_cast<size_t>(std::ceil(defaults[P::parts_settle_ms] /
                                                              defaults[P::analysis_hop_ms])) +
                                2;
    ASSERT_GE(a.size(), b.size());
    ASSERT_LE(a.size(), b.size() + padding_frames);
    for (size_t i = 0; i < b.size(); ++i) {
        EXPECT_EQ(a[i].frame_end_sample, b[i].frame_end_sample) << i;
        EXPECT_EQ(a[i].loudness_db, b[i].loudness_db) << i;
        EXPECT_EQ(a[i].brightness_hz, b[i].brightness_hz) << i;
        EXPECT_EQ(a[i].noisiness, b[i].noisiness) << i;
        EXPECT_EQ(a[i].pitch_hz, b[i].pitch_hz) << i;
        EXPECT_EQ(a[i].onset_odf, b[i].onset_odf) << i;
        EXPECT_EQ(a[i].onset, b[i].onset) << i;
        EXPECT_EQ(a[i].hit_db, b[i].hit_db) << i;
        EXPECT_EQ(a[i].part, b[i].part) << i;
        EXPECT_EQ(a[i].part_decided, b[i].part_decided) << i;
        if (a[i].onset) {
            EXPECT_EQ(a[i].onset_sample, b[i].onset_sample) << i;
        }
    }
}

TEST_F(RunFileTest, AnalyseFileGivesTheEnginesFeaturesWithoutSynthesis) {
    const double fs = 44100;
    const test::DrumSignal drums = test::drum_pattern(fs, 2.5, 9);
    const fs::path path = write("drums.wav", drums.audio, fs);
    Engine engine;
    FeatureList from_engine;
    engine.set_observer(&from_engine);
    run_file(path, engine);

    Analyzer analyzer;
    std::vector<Features> all, onsets_only;
    const RunSummary summary = analyse_file(path, analyzer, Settings{}, FeatureSet{},
                                            [&](const Features& f) { all.push_back(f); });
    EXPECT_EQ(summary.frames, static_cast<int64_t>(drums.audio.size()));
    expect_same_features(all, from_engine.frames);
    EXPECT_GT(std::count_if(all.begin(), all.end(), [](const Features& f) { return f.onset; }), 5);

    analyse_file(path, analyzer, Settings{}, FeatureSet::none(),
                 [&](const Features& f) { onsets_only.push_back(f); });
    ASSERT_EQ(onsets_only.size(), all.size());
    for (size_t i = 0; i < all.size(); ++i) {
        EXPECT_EQ(onsets_only[i].onset, all[i].onset) << i;
        EXPECT_EQ(onsets_only[i].onset_sample, all[i].onset_sample) << i;
        EXPECT_EQ(onsets_only[i].loudness_db, Features{}.loudness_db) << i;  // not computed
        EXPECT_EQ(onsets_only[i].brightness_hz, 0.0) << i;
    }
}

TEST_F(RunFileTest, RejectsUnsupportedRatesNamingTheFile) {
    const fs::path path = write("slow.wav", std::vector<float>(4000, 0.1f), 4000);
    Engine engine;
    Analyzer analyzer;
    for (const bool analysis_only : {false, true}) {
        try {
            if (analysis_only)
                analyse_file(path, analyzer, Settings{}, FeatureSet{}, [](const Features&) {});
            else
                run_file(path, engine);
            ADD_FAILURE() << "accepted a 4 kHz file";
        } catch (const std::runtime_error& e) {
            EXPECT_THAT(e.what(), HasSubstr(path.string()));
            EXPECT_THAT(e.what(), HasSubstr("4000"));
        }
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

// The same samples in memory (BufferSource) run as the file does, tail included; on_input sees
// every block the engine takes, the file's then the tail's silence; an engine run as prepared
// keeps its state, and a source at another rate is refused naming both.
TEST_F(RunFileTest, ABufferRunsAsTheFileAndOnInputSeesEveryBlock) {
    const double fs = 44100;
    const test::DrumSignal drums = test::drum_pattern(fs, 1.5, 5);
    const fs::path path = write("drums.wav", drums.audio, fs);
    const auto run = [&](AudioSource& source, RunPrepare prepare, Engine& engine) {
        std::vector<float> out, in;
        const RunSummary summary =
            run_source(source, engine,
                       {.on_output = [&](const float* const* v,
                                         int n) { out.insert(out.end(), v[0], v[0] + n); },
                        .on_input = [&](const float* const* x,
                                        int n) { in.insert(in.end(), x[0], x[0] + n); }},
                       RunTail::ring_out, prepare);
        EXPECT_EQ(static_cast<int64_t>(in.size()), summary.frames + summary.tail_frames);
        EXPECT_EQ(in.size(), out.size());
        EXPECT_TRUE(std::equal(drums.audio.begin(), drums.audio.end(), in.begin()));
        EXPECT_TRUE(std::all_of(in.begin() + static_cast<int64_t>(drums.audio.size()), in.end(),
                                [](float x) { return x == 0.0f; }));
        return out;
    };
    Engine from_file, from_buffer, prepared;
    FileSource file(path, kStreamBlockFrames);
    BufferSource buffer({drums.audio.data()}, static_cast<int64_t>(drums.audio.size()), fs,
                        "drums");
    const std::vector<float> expected = run(file, RunPrepare::engine, from_file);
    EXPECT_GT(expected.size(), drums.audio.size());
    EXPECT_EQ(run(buffer, RunPrepare::engine, from_buffer), expected);
    prepared.prepare({.sample_rate_hz = fs, .max_block = kStreamBlockFrames, .channels = 1});
    BufferSource again({drums.audio.data()}, static_cast<int64_t>(drums.audio.size()), fs, "drums");
    EXPECT_EQ(run(again, RunPrepare::none, prepared), expected);

    BufferSource other_rate({drums.audio.data()}, 100, 48000, "drums");
    try {
        run_source(other_rate, prepared, {}, RunTail::none, RunPrepare::none);
        ADD_FAILURE() << "accepted a source at another rate than the engine's";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(),
                    HasSubstr("drums: sample rate 48000 Hz, the engine runs at 44100 Hz"));
    }
}

}  // namespace
}  // namespace tactus
