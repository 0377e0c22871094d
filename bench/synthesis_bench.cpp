// The mapping and synthesis stages on the Amen break's real vibration program (44.1 kHz,
// default settings): Mapper per analysis frame; Voice (oscillator x envelope x amplitude) per
// output sample, a control frame applied every hop.
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_input.hpp"
#include "tactus/analysis/analyzer.hpp"
#include "tactus/mapping/mapper.hpp"
#include "tactus/synthesis/voice.hpp"

namespace tactus::bench {
namespace {

void MapperMap(benchmark::State& state) {
    // The features of every analysis frame, computed once.
    static const std::vector<Features> features = [] {
        Analyzer analyzer;
        analyzer.prepare(kRateHz, Settings{});
        std::vector<Features> out;
        const int hop = analyzer.hop_samples();
        for (size_t i = 0; i + hop <= amen().size(); i += hop)
            if (analyzer.write(amen().data() + i, hop)) out.push_back(analyzer.analyse());
        return out;
    }();
    Mapper mapper;
    mapper.prepare(Settings{}, kRateHz / hop_samples());
    for (auto _ : state) {
        mapper.reset();
        for (const Features& f : features) benchmark::DoNotOptimize(mapper.map(f));
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(features.size()));
    state.SetLabel("items = analysis frames");
}
BENCHMARK(MapperMap);

void VoiceRender(benchmark::State& state) {
    const Settings settings;
    const std::vector<ControlFrame>& control = amen_control();
    const int hop = hop_samples(settings);
    Voice voice;
    voice.prepare(kRateHz, settings[P::post_band_high_hz]);
    std::vector<float> out(static_cast<size_t>(hop));
    for (auto _ : state) {
        voice.reset();
        for (const ControlFrame& frame : control) {
            voice.render(out.data(), hop);
            voice.apply(frame);
            benchmark::DoNotOptimize(out.data());
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(control.size()) * hop);
    state.SetLabel("items = samples");
}
BENCHMARK(VoiceRender);

}  // namespace
}  // namespace tactus::bench
