// The analysis stage, one component at a time, on the Amen break at 44.1 kHz with the default
// settings: the STFT frame, each feature, YIN pitch, the onset detector, and the whole Analyzer.
// Frame-based components report frames/s (one frame per hop); sample-based ones samples/s.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "bench_input.hpp"
#include "tactus/analysis/analyzer.hpp"
#include "tactus/analysis/brightness.hpp"
#include "tactus/analysis/loudness.hpp"
#include "tactus/analysis/noisiness.hpp"
#include "tactus/analysis/onset_detector.hpp"
#include "tactus/analysis/pitch_yin.hpp"
#include "tactus/analysis/stft_frame.hpp"
#include "tactus/core/units.hpp"
#include "tactus/dsp/resampler.hpp"
#include "tactus/dsp/sample_history.hpp"

namespace tactus::bench {
namespace {

constexpr double kAnalysisRateHz = Analyzer::kAnalysisRateHz;

// The STFT window, sized as Analyzer::prepare sizes it (the Analyzer does not expose it).
int window_samples(const Settings& s) {
    return nearest_fft_size(ms_to_samples(s[P::analysis_window_ms], kAnalysisRateHz));
}

// Runs `analyse(history)` once per hop over the Amen break at the analysis rate; counts frames.
template <typename Analyse>
void per_frame(benchmark::State& state, int history_samples, Analyse analyse) {
    const std::vector<float>& in = amen_analysis();
    const int hop = analysis_hop_samples();
    SampleHistory history;
    history.prepare(history_samples);
    for (auto _ : state) {
        history.reset();
        for (size_t i = 0; i + hop <= in.size(); i += hop) {
            history.write(in.data() + i, hop);
            analyse(history);
        }
    }
    set_items(state, in.size() / hop, "analysis frames");
}

void StftFrameAnalyse(benchmark::State& state) {
    StftFrame stft;
    stft.prepare(window_samples({}), kAnalysisRateHz);
    per_frame(state, stft.window_samples(), [&](const SampleHistory& h) {
        stft.analyse(h);
        benchmark::DoNotOptimize(stft.magnitudes().data());
    });
}
BENCHMARK(StftFrameAnalyse);

// Brightness and noisiness read a ready spectrum: STFT frames of the Amen break, computed once.
struct Spectra {
    std::vector<std::vector<float>> magnitudes, powers;
    int bins = 0;
    double bin_hz = 0;
};
const Spectra& amen_spectra() {
    static const Spectra spectra = [] {
        Spectra s;
        StftFrame stft;
        stft.prepare(window_samples({}), kAnalysisRateHz);
        SampleHistory history;
        history.prepare(stft.window_samples());
        const std::vector<float>& in = amen_analysis();
        const int hop = analysis_hop_samples();
        for (size_t i = 0; i + hop <= in.size(); i += hop) {
            history.write(in.data() + i, hop);
            stft.analyse(history);
            s.magnitudes.push_back(stft.magnitudes());
            s.powers.push_back(stft.powers());
        }
        s.bins = stft.bins();
        s.bin_hz = stft.bin_hz();
        return s;
    }();
    return spectra;
}

void Brightness(benchmark::State& state) {
    const Spectra& s = amen_spectra();
    tactus::Brightness brightness;
    brightness.prepare(s.bins, s.bin_hz, tactus::Settings{}[tactus::P::brightness_max_hz]);
    for (auto _ : state)
        for (const auto& m : s.magnitudes) benchmark::DoNotOptimize(brightness.centroid_hz(m));
    set_items(state, s.magnitudes.size(), "analysis frames");
}
BENCHMARK(Brightness);

void Noisiness(benchmark::State& state) {
    const Spectra& s = amen_spectra();
    tactus::Noisiness noisiness;
    noisiness.prepare(s.bins, s.bin_hz);
    for (auto _ : state)
        for (const auto& p : s.powers) benchmark::DoNotOptimize(noisiness.compute(p));
    set_items(state, s.powers.size(), "analysis frames");
}
BENCHMARK(Noisiness);

void Loudness(benchmark::State& state) {
    const Settings settings;
    const std::vector<float>& in = amen();  // at the input rate, as the Analyzer runs it
    const int hop = static_cast<int>(kRateHz / frame_rate_hz());
    tactus::Loudness loudness;
    loudness.prepare({.sample_rate_hz = kRateHz}, settings[P::loudness_window_ms]);
    for (auto _ : state) {
        loudness.reset();
        for (size_t i = 0; i + hop <= in.size(); i += hop) {
            loudness.process(in.data() + i, hop);
            benchmark::DoNotOptimize(loudness.loudness_db());
        }
    }
    set_items(state, in.size(), "samples");
}
BENCHMARK(Loudness);

void PitchYinAnalyse(benchmark::State& state) {
    const Settings s;
    PitchYin pitch;
    pitch.prepare({.sample_rate_hz = kAnalysisRateHz},
                  {.min_hz = s[P::pitch_min_hz],
                   .max_hz = std::min(s[P::pitch_max_hz], 0.45 * kAnalysisRateHz),
                   .threshold = s[P::pitch_threshold]});  // as the Analyzer clamps it
    per_frame(state, pitch.span_samples(),
              [&](const SampleHistory& h) { benchmark::DoNotOptimize(pitch.analyse(h)); });
}
BENCHMARK(PitchYinAnalyse);

void OnsetDetectorAnalyse(benchmark::State& state) {
    const Settings s;
    OnsetDetector onsets;
    onsets.prepare({.sample_rate_hz = kAnalysisRateHz}, analysis_hop_samples(),
                   Analyzer::onset_settings(s));
    per_frame(state, onsets.span_samples(), [&](const SampleHistory& h) {
        benchmark::DoNotOptimize(onsets.analyse(h, {0.0, 0.0}));
    });
}
BENCHMARK(OnsetDetectorAnalyse);

// The Resampler from the input rate to the analysis rate, per input sample.
void ResamplerToAnalysisRate(benchmark::State& state) {
    const std::vector<float>& in = amen();
    Resampler resampler;
    constexpr int kBlock = 128;
    resampler.prepare(kRateHz, kAnalysisRateHz, kBlock);
    std::vector<float> out(kBlock);
    for (auto _ : state) {
        resampler.reset();
        for (size_t i = 0; i + kBlock <= in.size(); i += kBlock)
            benchmark::DoNotOptimize(resampler.process(in.data() + i, kBlock, out.data()));
    }
    set_items(state, in.size(), "samples");
}
BENCHMARK(ResamplerToAnalysisRate);

// The whole analysis stage (resampler, YIN every ~10 ms, the rest every hop), per input sample.
void WholeAnalyzer(benchmark::State& state) {
    const std::vector<float>& in = amen();
    Analyzer analyzer;
    analyzer.prepare({.sample_rate_hz = kRateHz}, Settings{});
    for (auto _ : state) {
        analyzer.reset();
        for (size_t i = 0; i < in.size();) {
            const auto chunk = std::min<size_t>(in.size() - i, analyzer.samples_to_next_frame());
            if (analyzer.process(in.data() + i, static_cast<int>(chunk)))
                benchmark::DoNotOptimize(analyzer.analyse());
            i += chunk;
        }
    }
    set_items(state, in.size(), "samples");
}
BENCHMARK(WholeAnalyzer);

}  // namespace
}  // namespace tactus::bench
