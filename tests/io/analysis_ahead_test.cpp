// io/analysis_ahead.hpp through run_file (RunAnalysis::ahead): the analysis on a thread of its
// own renders what the engine's own analysis does, bit for bit, its frames included. In
// engine_tests, labelled threads: make test-tsan runs it under ThreadSanitizer.
#include "tactus/io/analysis_ahead.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <thread>
#include <utility>
#include <vector>

#include "support/signals.hpp"
#include "support/sound_file.hpp"
#include "support/temp_dir.hpp"
#include "tactus/io/run_file.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;

using AnalysisAheadTest = test::TempDirTest;

class FeatureList final : public FrameObserver {
  public:
    void on_frame(const Features& f, const ControlFrame&) noexcept override { frames.push_back(f); }
    std::vector<Features> frames;
};

// RunAnalysis::ahead: the same vibration, tail and frames as the engine analysing, bit for bit,
// for the channels' mean (their loudness summed) and for one chosen channel, for a file of many
// blocks and one that ends in its seventh; a file shorter than kAheadMinS runs in the engine.
TEST_F(AnalysisAheadTest, RendersAsTheEngineAnalysing) {
    const double fs = 48000;
    for (const double seconds : {3.0, kAheadMinS + 0.01, 0.1}) {
        const test::DrumSignal left = test::drum_pattern(fs, seconds, 11);
        const test::DrumSignal right = test::drum_pattern(fs, seconds, 12);
        std::vector<float> interleaved;
        for (size_t i = 0; i < left.audio.size(); ++i)
            interleaved.insert(interleaved.end(), {left.audio[i], 0.5f * right.audio[i]});
        const fs::path path = dir_ / "stereo.wav";
        ASSERT_NO_FATAL_FAILURE(test::write_sound_file(path, interleaved, fs, 2));
        for (const int channel : {-1, 1}) {
            const auto render = [&](RunAnalysis analysis) {
                Engine engine;  // the default preset, music
                engine.set_input_channel(channel);
                FeatureList frames;
                engine.set_observer(&frames);
                std::vector<float> out;
                const RunSummary summary =
                    run_file(path, engine,
                             {.on_output = [&](const float* const* v,
                                               int n) { out.insert(out.end(), v[0], v[0] + n); }},
                             RunTail::ring_out, analysis);
                EXPECT_EQ(summary.analysed_ahead, analysis == RunAnalysis::ahead &&
                                                      seconds >= kAheadMinS &&
                                                      std::thread::hardware_concurrency() >= 2);
                return std::pair(out, frames.frames);
            };
            const auto [expected, expected_frames] = render(RunAnalysis::engine);
            const auto [ahead, ahead_frames] = render(RunAnalysis::ahead);
            EXPECT_GT(expected.size(), left.audio.size()) << seconds << " s, channel " << channel;
            EXPECT_EQ(ahead, expected) << seconds << " s, channel " << channel;
            EXPECT_TRUE(ahead_frames == expected_frames) << seconds << " s, channel " << channel;
        }
    }
}

// An engine run ahead must not have taken input since it was prepared (its analysis would have
// heard what a new one has not): one prepared by its host runs ahead, one that has run stays in
// the engine, and both give what the engine analysing gives.
TEST_F(AnalysisAheadTest, OnlyAnEngineThatHasTakenNoInputRunsAhead) {
    const double fs = 48000;
    const test::DrumSignal drums = test::drum_pattern(fs, 2.0, 13);
    const int64_t frames = static_cast<int64_t>(drums.audio.size());
    const auto render = [&](Engine& engine, RunAnalysis analysis, bool& ahead) {
        std::vector<float> out;
        BufferSource source({drums.audio.data()}, frames, fs, "drums");
        ahead = run_source(source, engine,
                           {.on_output = [&](const float* const* v,
                                             int n) { out.insert(out.end(), v[0], v[0] + n); }},
                           RunTail::ring_out, RunPrepare::none, analysis)
                    .analysed_ahead;
        return out;
    };
    const ProcessSpec spec{.sample_rate_hz = fs, .max_block = kStreamBlockFrames, .channels = 1};
    Engine analysing, prepared, used;
    bool ahead = true;
    analysing.prepare(spec);
    const std::vector<float> expected = render(analysing, RunAnalysis::engine, ahead);
    EXPECT_FALSE(ahead);
    prepared.prepare(spec);
    EXPECT_EQ(render(prepared, RunAnalysis::ahead, ahead), expected);
    EXPECT_EQ(ahead, std::thread::hardware_concurrency() >= 2);
    used.prepare(spec);
    std::vector<float> first(64), out(64);
    const float* in[] = {first.data()};
    float* to[] = {out.data()};
    used.process(in, to, 64);
    render(used, RunAnalysis::ahead, ahead);
    EXPECT_FALSE(ahead);
}

}  // namespace
}  // namespace tactus
