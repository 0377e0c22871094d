// Analyzer: frames fall on the hop grid whatever the write block size and the features are
// bit-identical for any split; a 997 Hz sine gives loudness -3.01 dB, brightness 997 Hz, low
// noisiness, pitch 997 Hz; silence gives floor values; extreme finite input (+60 dBFS, the
// largest float) gives finite features; clicks at exact sample times are each detected once
// with onset_sample within 1 ms and the decision within 10 ms after the onset.
#include "tactus/analysis/analyzer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "support/signals.hpp"
#include "tactus/core/units.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus {
namespace {

// Feeds x in blocks of `block` (further split at frame boundaries) and collects every frame.
std::vector<Features> run(Analyzer& analyzer, const std::vector<float>& x, int block) {
    std::vector<Features> frames;
    size_t done = 0;
    while (done < x.size()) {
        const int size = static_cast<int>(std::min<size_t>(x.size() - done, block));
        int written = 0;
        while (written < size) {
            const int chunk = std::min(size - written, analyzer.samples_to_next_frame());
            if (analyzer.process(x.data() + done + written, chunk))
                frames.push_back(analyzer.analyse());
            written += chunk;
        }
        done += static_cast<size_t>(size);
    }
    return frames;
}

TEST(Analyzer, FramesAreOnTheHopGridAndIndependentOfBlockSize) {
    const double fs = 48000;
    const test::DrumSignal drums = test::drum_pattern(fs, 3.0, 5);
    Analyzer reference;
    reference.prepare({.sample_rate_hz = fs}, Settings{});
    // The hop is whole analysis samples (16 kHz, a third of 48 kHz); frame k ends after the
    // input its last analysis sample reads: floor((k hop - 1) * 3) + 1.
    const int64_t hop = reference.hop_analysis_samples();
    EXPECT_EQ(reference.analysis_rate_hz(), Analyzer::kAnalysisRateHz);
    EXPECT_EQ(hop, ms_to_samples(Settings{}[P::analysis_hop_ms], Analyzer::kAnalysisRateHz));
    EXPECT_DOUBLE_EQ(reference.hop_samples(), 3.0 * static_cast<double>(hop));
    const auto expected = run(reference, drums.audio, 4096);
    ASSERT_EQ(expected.size(), (drums.audio.size() + 2) / static_cast<size_t>(3 * hop));
    for (size_t i = 0; i < expected.size(); ++i)
        ASSERT_EQ(expected[i].frame_end_sample, (static_cast<int64_t>(i + 1) * hop - 1) * 3 + 1);
    for (int block : {1, 7, 64, 480}) {
        Analyzer analyzer;
        analyzer.prepare({.sample_rate_hz = fs}, Settings{});
        const auto frames = run(analyzer, drums.audio, block);
        ASSERT_EQ(frames.size(), expected.size()) << "block " << block;
        for (size_t i = 0; i < frames.size(); ++i) {
            const Features &a = frames[i], &b = expected[i];
            ASSERT_TRUE(a.frame_end_sample == b.frame_end_sample &&
                        a.loudness_db == b.loudness_db && a.brightness_hz == b.brightness_hz &&
                        a.noisiness == b.noisiness && a.pitch_hz == b.pitch_hz &&
                        a.pitch_confidence == b.pitch_confidence && a.onset_odf == b.onset_odf &&
                        a.onset == b.onset && a.onset_sample == b.onset_sample)
                << "block " << block << ", frame " << i;
        }
    }
}

TEST(Analyzer, SineFeatures) {
    for (double fs : {44100.0, 48000.0}) {
        Analyzer analyzer;
        analyzer.prepare({.sample_rate_hz = fs}, Settings{});
        const auto frames = run(analyzer, test::sine(997.0, fs, static_cast<size_t>(fs)), 512);
        const Features& f = frames.back();
        EXPECT_NEAR(f.loudness_db, -3.01, 0.2) << fs;
        EXPECT_NEAR(f.brightness_hz, 997.0, 5.0) << fs;
        EXPECT_LT(f.noisiness, 0.05) << fs;
        EXPECT_NEAR(f.pitch_hz, 997.0, 9.97) << fs;
        EXPECT_GT(f.pitch_confidence, 0.9) << fs;
        EXPECT_NEAR(feature_value(f, FeatureSource::tonality), 1.0 - f.noisiness, 1e-12);
        int onsets = 0;
        for (const auto& frame : frames) onsets += frame.onset;
        EXPECT_EQ(onsets, 1) << "only the sine's start is an onset";
    }
}

TEST(Analyzer, SilenceFeatures) {
    Analyzer analyzer;
    analyzer.prepare({.sample_rate_hz = 48000}, Settings{});
    const auto frames = run(analyzer, std::vector<float>(48000, 0.0f), 1000);
    ASSERT_FALSE(frames.empty());
    for (const Features& f : frames) {
        EXPECT_EQ(f.loudness_db, Loudness::kFloorDb);
        EXPECT_EQ(f.brightness_hz, 0.0);
        EXPECT_EQ(f.noisiness, 0.0);
        EXPECT_EQ(f.pitch_hz, 0.0);
        EXPECT_EQ(f.onset_odf, 0.0);
        EXPECT_FALSE(f.onset);
    }
}

// Input far beyond full scale (+60 dBFS, and the largest float) is finite, so no NaN check
// removes it: every feature must stay finite (a NaN feature would reach the synthesiser).
TEST(Analyzer, ExtremeFiniteInputGivesFiniteFeatures) {
    const double fs = 48000;
    std::vector<float> x = test::sine(200.0, fs, static_cast<size_t>(fs), 0.5);
    for (size_t i = 12000; i < 14000; ++i) x[i] = (i % 2 ? -1000.0f : 1000.0f);
    for (size_t i = 20000; i < 26000; ++i) x[i] = 1000.0f;  // a DC block at +60 dBFS
    for (size_t i = 30000; i < 30064; ++i)
        x[i] = (i % 2 ? -1.0f : 1.0f) * std::numeric_limits<float>::max();
    Analyzer analyzer;
    analyzer.prepare({.sample_rate_hz = fs}, Settings{});
    int bad = 0;
    for (const Features& f : run(analyzer, x, 480)) {
        const bool finite = std::isfinite(f.loudness_db) && std::isfinite(f.brightness_hz) &&
                            std::isfinite(f.noisiness) && std::isfinite(f.pitch_hz) &&
                            std::isfinite(f.pitch_confidence) && std::isfinite(f.onset_odf);
        if (!finite && bad++ < 3)
            ADD_FAILURE() << "frame ending at " << f.frame_end_sample << ": loudness "
                          << f.loudness_db << ", brightness " << f.brightness_hz << ", noisiness "
                          << f.noisiness << ", pitch " << f.pitch_hz << " (confidence "
                          << f.pitch_confidence << "), odf " << f.onset_odf;
    }
    EXPECT_EQ(bad, 0) << "frames with non-finite features";
}

TEST(Analyzer, ClicksAreDetectedOnceNearTheirTrueTime) {
    for (double fs : {8000.0, 44100.0, 48000.0}) {
        std::vector<float> x(static_cast<size_t>(4 * fs), 0.0f);
        std::vector<int64_t> truth;
        test::Random random(3);
        for (int k = 0; k < 12; ++k) {
            const auto at = static_cast<int64_t>(std::llround((0.2 + 0.3 * k) * fs)) + 13 * k;
            truth.push_back(at);
            if (k % 2 == 0) {
                x[static_cast<size_t>(at)] = 0.6f;
            } else {
                for (int64_t i = 0; i < static_cast<int64_t>(0.04 * fs); ++i)
                    x[static_cast<size_t>(at + i)] = static_cast<float>(
                        0.4 * std::exp(-double(i) / (0.006 * fs)) * random.uniform(-1, 1));
            }
        }
        Analyzer analyzer;
        analyzer.prepare({.sample_rate_hz = fs}, Settings{});
        std::vector<const Features*> onsets;
        const auto frames = run(analyzer, x, 333);
        for (const auto& f : frames)
            if (f.onset) onsets.push_back(&f);
        const double ms = fs / 1000.0;
        ASSERT_EQ(onsets.size(), truth.size()) << fs;
        for (size_t i = 0; i < truth.size(); ++i) {
            EXPECT_NEAR(static_cast<double>(onsets[i]->onset_sample), static_cast<double>(truth[i]),
                        1.0 * ms)
                << "click " << i << " at " << fs;
            EXPECT_GT(onsets[i]->frame_end_sample, truth[i]) << "click " << i << " at " << fs;
            EXPECT_LE(onsets[i]->frame_end_sample - truth[i], 10.0 * ms)
                << "click " << i << " at " << fs;
        }
    }
}

}  // namespace
}  // namespace tactus
