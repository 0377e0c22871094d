#include "bench_input.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "tactus/analysis/analyzer.hpp"
#include "tactus/core/units.hpp"
#include "tactus/dsp/resampler.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/mapping/mapper.hpp"
#include "tactus/synthesis/voice.hpp"

namespace tactus::bench {
namespace {

struct EngineRates {
    double frame_rate_hz;
    int rate_divisor;
};

const EngineRates& engine_rates() {
    static const EngineRates rates = [] {
        Engine engine;
        engine.prepare(kRateHz, Engine::kMaxBlock);
        return EngineRates{kRateHz / engine.hop_samples(), engine.rate_divisor()};
    }();
    return rates;
}

int64_t ceil_div(int64_t a, int64_t b) {
    return (a + b - 1) / b;
}

}  // namespace

const std::vector<float>& amen() {
    static const std::vector<float> samples = [] {
        MonoAudio audio = read_mono(kAmenPath);
        if (audio.sample_rate_hz != kRateHz)
            throw std::runtime_error("loop_amen_full.flac: expected 44.1 kHz");
        return std::move(audio.samples);
    }();
    return samples;
}

double frame_rate_hz() {
    return engine_rates().frame_rate_hz;
}

int rate_divisor() {
    return engine_rates().rate_divisor;
}

double internal_rate_hz() {
    return kRateHz / rate_divisor();
}

const std::vector<float>& amen_analysis() {
    static const std::vector<float> samples = [] {
        const std::vector<float>& in = amen();
        Resampler resampler;
        resampler.prepare(kRateHz, Analyzer::kAnalysisRateHz, Engine::kMaxBlock);
        std::vector<float> out(in.size());
        size_t written = 0;
        for (size_t i = 0; i < in.size(); i += Engine::kMaxBlock) {
            const auto count = std::min<size_t>(in.size() - i, Engine::kMaxBlock);
            written += static_cast<size_t>(
                resampler.process(in.data() + i, static_cast<int>(count), out.data() + written));
        }
        out.resize(written);
        return out;
    }();
    return samples;
}

int analysis_hop_samples() {
    return static_cast<int>(
        ms_to_samples(Settings{}[P::analysis_hop_ms], Analyzer::kAnalysisRateHz));
}

const std::vector<Features>& amen_features() {
    static const std::vector<Features> features = [] {
        Analyzer analyzer;
        analyzer.prepare({.sample_rate_hz = kRateHz}, Settings{});
        std::vector<Features> out;
        const std::vector<float>& in = amen();
        for (size_t i = 0; i < in.size();) {
            const auto chunk = std::min<size_t>(in.size() - i, analyzer.samples_to_next_frame());
            if (analyzer.process(in.data() + i, static_cast<int>(chunk)))
                out.push_back(analyzer.analyse());
            i += chunk;
        }
        return out;
    }();
    return features;
}

const std::vector<ControlFrame>& amen_control() {
    static const std::vector<ControlFrame> frames = [] {
        Mapper mapper;
        mapper.prepare(Settings{}, frame_rate_hz());
        std::vector<ControlFrame> out;
        for (const Features& f : amen_features()) out.push_back(mapper.map(f));
        return out;
    }();
    return frames;
}

const std::vector<int>& internal_samples_per_hop() {
    static const std::vector<int> counts = [] {
        // Internal sample k stands at input sample k * divisor: those due for the input
        // samples since the previous frame's end.
        const int64_t divisor = rate_divisor();
        std::vector<int> out(amen_control().size());
        int64_t p = 0;
        for (size_t f = 0; f < out.size(); ++f) {
            const int64_t end = amen_features()[f].frame_end_sample;
            out[f] = static_cast<int>(ceil_div(end, divisor) - ceil_div(p, divisor));
            p = end;
        }
        return out;
    }();
    return counts;
}

const std::vector<float>& amen_vibration() {
    static const std::vector<float> samples = [] {
        Voice voice;
        voice.prepare({.sample_rate_hz = internal_rate_hz()}, Settings{}[P::post_band_high_hz]);
        std::vector<float> out;
        for (size_t f = 0; f < amen_control().size(); ++f) {
            const size_t start = out.size();
            out.resize(start + internal_samples_per_hop()[f]);
            voice.process(out.data() + start, internal_samples_per_hop()[f]);
            voice.apply(amen_control()[f]);
        }
        return out;
    }();
    return samples;
}

void set_items(benchmark::State& state, size_t count, const char* what) {
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(count));
    state.SetLabel(std::string("items = ") + what);
}

void set_real_time(benchmark::State& state, size_t samples) {
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(samples));
    state.counters["x_real_time"] = benchmark::Counter(
        static_cast<double>(samples) / kRateHz * state.iterations(), benchmark::Counter::kIsRate);
}

}  // namespace tactus::bench
