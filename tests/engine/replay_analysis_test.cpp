// Engine::replay_analysis: a recorded analysis played back in place of the analysis renders,
// bit for bit, what analysing the input again renders, for settings that change no parameter
// the analysis reads (mapping, envelope, synthesis, post-processing; a mapping source the
// recording's engine did not map included), in any split into blocks, from two input channels;
// the input is then not read by the analysis (silence in, the same vibration out); a recording
// shorter than the input says so (replay_ran_out). Analyzer::reads names every parameter the
// features depend on: changing any other leaves every frame as it was.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "support/signals.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus {
namespace {

constexpr double kRate = 44100;

// Two channels of drums (the second quieter and later): the loudness is their BS.1770 sum.
std::vector<std::vector<float>> stereo_drums() {
    const std::vector<float> drums = test::drum_pattern(kRate, 4.0, 5).audio;
    std::vector<float> right(drums.size(), 0.0f);
    for (size_t i = 300; i < drums.size(); ++i) right[i] = 0.5f * drums[i - 300];
    return {drums, right};
}

struct Rendered {
    std::vector<float> vibration;
    RecordedAnalysis frames;
    bool ran_out = false;
};

// The engine's vibration for `input` in blocks cycling through `blocks`, and its frames.
Rendered run(const Settings& settings, const std::vector<std::vector<float>>& input,
             const std::vector<int>& blocks,
             std::shared_ptr<const RecordedAnalysis> recording = {}) {
    Engine engine(settings);
    engine.enable_frame_queue();
    engine.replay_analysis(std::move(recording));
    engine.prepare({.sample_rate_hz = kRate, .max_block = Engine::kMaxBlock, .channels = 2});
    Rendered out;
    const size_t n = input[0].size();
    out.vibration.resize(n);
    for (size_t done = 0, b = 0; done < n; ++b) {
        const auto count =
            std::min<size_t>(n - done, static_cast<size_t>(blocks[b % blocks.size()]));
        const float* in[] = {input[0].data() + done, input[1].data() + done};
        float* vib[] = {out.vibration.data() + done};
        engine.process(in, vib, static_cast<int>(count));
        for (AnalysisFrame f; engine.pop_frame(f);) out.frames.frames.push_back(f.features);
        done += count;
    }
    out.ran_out = engine.replay_ran_out();
    return out;
}

bool same_features(const Features& a, const Features& b) {
    const auto bits = [](double x) { return std::bit_cast<uint64_t>(x); };
    return a.frame_end_sample == b.frame_end_sample && bits(a.loudness_db) == bits(b.loudness_db) &&
           bits(a.brightness_hz) == bits(b.brightness_hz) &&
           bits(a.noisiness) == bits(b.noisiness) && bits(a.pitch_hz) == bits(b.pitch_hz) &&
           bits(a.pitch_confidence) == bits(b.pitch_confidence) &&
           bits(a.onset_odf) == bits(b.onset_odf) && a.onset == b.onset &&
           a.onset_sample == b.onset_sample && bits(a.hit_db) == bits(b.hit_db) &&
           bits(a.hit_brightness_hz) == bits(b.hit_brightness_hz) && a.part == b.part &&
           a.part_decided == b.part_decided && bits(a.hit_strength_db) == bits(b.hit_strength_db);
}

bool same_frames(const RecordedAnalysis& a, const RecordedAnalysis& b) {
    if (a.frames.size() != b.frames.size()) return false;
    for (size_t i = 0; i < a.frames.size(); ++i)
        if (!same_features(a.frames[i], b.frames[i])) return false;
    return true;
}

Settings with(std::initializer_list<std::pair<const char*, const char*>> values) {
    Settings s;
    for (const auto& [key, text] : values) s.set_from_text(*find_param(key), text);
    return s;
}

TEST(ReplayAnalysis, RendersWhatAnalysingAgainRendersBitForBit) {
    const auto input = stereo_drums();
    const auto recording = std::make_shared<const RecordedAnalysis>(run({}, input, {4096}).frames);
    ASSERT_GT(recording->frames.size(), 100u);
    for (const Settings& s :
         {Settings{}, with({{"envelope.decay_ms", "250"}}),
          with({{"mapping.frequency.curve", "lin"}, {"flutter.equalize", "on"}}),
          with({{"mapping.amplitude.source", "pitch_confidence"}, {"post.drive_db", "6"}}),
          with({{"flutter.weight", "0.5"}, {"parts.kick.gain_db", "-6"}})}) {
        const Rendered analysed = run(s, input, {4096});
        ASSERT_GT(test::peak(analysed.vibration), 0.05);
        for (const std::vector<int>& blocks : {std::vector<int>{4096}, {1, 700, 64, 4096, 13}}) {
            const Rendered replayed = run(s, input, blocks, recording);
            EXPECT_TRUE(test::same_bits(replayed.vibration, analysed.vibration)) << blocks.size();
            EXPECT_TRUE(same_frames(replayed.frames, analysed.frames));
            EXPECT_FALSE(replayed.ran_out);
        }
    }
}

TEST(ReplayAnalysis, DoesNotAnalyseTheInput) {
    const auto input = stereo_drums();
    const Rendered analysed = run({}, input, {4096});
    const auto recording = std::make_shared<const RecordedAnalysis>(analysed.frames);
    const std::vector<std::vector<float>> silence(2, std::vector<float>(input[0].size(), 0.0f));
    EXPECT_TRUE(test::same_bits(run({}, silence, {512}, recording).vibration, analysed.vibration));
}

TEST(ReplayAnalysis, SaysWhenTheRecordingRanOut) {
    const auto input = stereo_drums();
    auto half = run({}, input, {4096}).frames;
    half.frames.resize(half.frames.size() / 2);
    EXPECT_TRUE(run({}, input, {4096}, std::make_shared<const RecordedAnalysis>(half)).ran_out);
}

TEST(ReplayAnalysis, TheAnalysisReadsOnlyTheParametersItNames) {
    const auto input = stereo_drums();
    const RecordedAnalysis reference = run({}, input, {4096}).frames;
    int unread = 0;
    for (const ParamSpec& p : param_table()) {
        if (Analyzer::reads(p.param)) continue;
        Settings s;
        s.set(p.param, p.default_value != p.max ? p.max : p.min);
        EXPECT_TRUE(same_frames(run(s, input, {4096}).frames, reference)) << p.key;
        ++unread;
    }
    EXPECT_GT(unread, 50);
}

}  // namespace
}  // namespace tactus
