// OnsetDecisions: an onset is reported once, on the frame that decides its part, with that
// frame's part and strength; one detected and decided on the same frame at once; one the next
// onset or the end overtakes, then, with its own frame's values. On the Amen break through the
// engine (and 50 ms of silence), every onset is decided parts.settle_ms (within a hop) after its
// start, in order, and in more than one part.
#include "tactus/engine/onset_decisions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <vector>

#include "support/sounds.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"

namespace tactus {
namespace {

Features frame(int64_t end, bool onset = false, bool decided = false,
               DrumPart part = DrumPart::other, double strength_db = -120) {
    Features f;
    f.frame_end_sample = end;
    f.onset = onset;
    f.onset_sample = end - 50;
    f.part_decided = decided;
    f.part = part;
    f.hit_strength_db = strength_db;
    return f;
}

TEST(OnsetDecisions, ReportsAnOnsetWhenItsPartIsDecided) {
    OnsetDecisions decisions;
    std::vector<DecidedOnset> got;
    const auto add = [&](const DecidedOnset& o) { got.push_back(o); };
    decisions.add(frame(100, true, false, DrumPart::kick, -30), add);  // the previous hit's part
    decisions.add(frame(164, false, false, DrumPart::kick, -20), add);
    EXPECT_TRUE(got.empty());
    decisions.add(frame(228, false, true, DrumPart::snare, -12.5), add);
    decisions.add(frame(292, false, false, DrumPart::snare, -12.5), add);
    decisions.finish(add);
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].onset_sample, 50);
    EXPECT_EQ(got[0].decided_sample, 100);
    EXPECT_EQ(got[0].part_sample, 228);
    EXPECT_EQ(got[0].part, DrumPart::snare);
    EXPECT_EQ(got[0].strength_db, -12.5);
    EXPECT_TRUE(got[0].part_decided);
}

TEST(OnsetDecisions, OneFrameCanDetectAndDecide) {
    OnsetDecisions decisions;
    std::vector<DecidedOnset> got;
    decisions.add(frame(100, true, true, DrumPart::hat, -18),
                  [&](const DecidedOnset& o) { got.push_back(o); });
    ASSERT_EQ(got.size(), 1u);
    EXPECT_EQ(got[0].part, DrumPart::hat);
    EXPECT_EQ(got[0].part_sample, got[0].decided_sample);
}

TEST(OnsetDecisions, AnOnsetOvertakenIsReportedUndecided) {
    OnsetDecisions decisions;
    std::vector<DecidedOnset> got;
    const auto add = [&](const DecidedOnset& o) { got.push_back(o); };
    decisions.add(frame(100, true, false, DrumPart::kick, -30), add);
    decisions.add(frame(164, true, false, DrumPart::kick, -25), add);  // overtakes the first
    ASSERT_EQ(got.size(), 1u);
    EXPECT_FALSE(got[0].part_decided);
    EXPECT_EQ(got[0].decided_sample, 100);
    EXPECT_EQ(got[0].strength_db, -30);  // as it stood on its own frame
    decisions.finish(add);               // the input ends before the second is decided
    ASSERT_EQ(got.size(), 2u);
    EXPECT_EQ(got[1].decided_sample, 164);
    EXPECT_FALSE(got[1].part_decided);
    decisions.finish(add);
    decisions.add(frame(228, false, true), add);  // a decision with no onset waiting
    EXPECT_EQ(got.size(), 2u);
}

TEST(OnsetDecisions, EveryOnsetOfTheAmenBreakIsDecidedAfterTheSettleTime) {
    const std::filesystem::path amen = test::kAmen;
    if (!std::filesystem::exists(amen)) GTEST_SKIP() << amen << " not installed";
    MonoAudio audio = read_mono(amen);
    // 50 ms of silence after it: the last onset, near the end, is decided too.
    audio.samples.resize(audio.samples.size() + static_cast<size_t>(0.05 * audio.sample_rate_hz));
    Engine engine;
    engine.enable_frame_queue();
    constexpr int kBlock = 256;
    engine.prepare(audio.sample_rate_hz, kBlock);
    OnsetDecisions decisions;
    std::vector<DecidedOnset> got;
    int detected = 0;
    const auto add = [&](const DecidedOnset& o) { got.push_back(o); };
    std::vector<float> out(kBlock);
    for (size_t done = 0; done < audio.samples.size(); done += kBlock) {
        const int n = static_cast<int>(std::min<size_t>(kBlock, audio.samples.size() - done));
        engine.process(audio.samples.data() + done, out.data(), n);
        for (AnalysisFrame f; engine.pop_frame(f);) {
            detected += f.features.onset;
            decisions.add(f.features, add);
        }
    }
    decisions.finish(add);
    ASSERT_EQ(static_cast<int>(got.size()), detected);
    EXPECT_GT(detected, 40);
    const double settle_samples =
        engine.settings()[P::parts_settle_ms] * 1e-3 * audio.sample_rate_hz;
    // Onset starts are mapped back from the analysis rate, less the resampler's delay: 1 ms.
    const double slack = 1e-3 * audio.sample_rate_hz;
    std::set<DrumPart> parts;
    for (size_t i = 0; i < got.size(); ++i) {
        const DecidedOnset& o = got[i];
        EXPECT_TRUE(o.part_decided) << "onset " << i;
        // Decided on the first frame settle_ms after its start (or on its own frame, if later).
        EXPECT_GE(static_cast<double>(o.part_sample), o.onset_sample + settle_samples - slack) << i;
        EXPECT_LE(static_cast<double>(o.part_sample),
                  std::max<double>(static_cast<double>(o.decided_sample),
                                   o.onset_sample + settle_samples) +
                      engine.hop_samples() + slack)
            << i;
        EXPECT_LT(o.strength_db, 0.0);
        if (i > 0) {
            EXPECT_GT(o.onset_sample, got[i - 1].onset_sample);
        }
        parts.insert(o.part);
    }
    EXPECT_GE(parts.size(), 2u);
}

}  // namespace
}  // namespace tactus
