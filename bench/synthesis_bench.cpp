// The mapping and synthesis stages on the Amen break's real vibration program (default
// settings): Mapper per analysis frame; Voice (oscillator x envelope x amplitude) per sample at
// the engine's internal rate (11.025 kHz for the 44.1 kHz input), a control frame applied every
// hop.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "bench_input.hpp"
#include "tactus/mapping/mapper.hpp"
#include "tactus/synthesis/voice.hpp"

namespace tactus::bench {
namespace {

void MapperMap(benchmark::State& state) {
    const std::vector<Features>& features = amen_features();
    Mapper mapper;
    mapper.prepare(Settings{}, frame_rate_hz());
    for (auto _ : state) {
        mapper.reset();
        for (const Features& f : features) benchmark::DoNotOptimize(mapper.map(f));
    }
    set_items(state, features.size(), "analysis frames");
}
BENCHMARK(MapperMap);

void VoiceRender(benchmark::State& state) {
    const std::vector<ControlFrame>& control = amen_control();
    const std::vector<int>& counts = internal_samples_per_hop();
    Voice voice;
    voice.prepare({.sample_rate_hz = internal_rate_hz()}, Settings{}[P::post_band_high_hz]);
    std::vector<float> out(static_cast<size_t>(*std::max_element(counts.begin(), counts.end())));
    for (auto _ : state) {
        voice.reset();
        for (size_t f = 0; f < control.size(); ++f) {
            voice.process(out.data(), counts[f]);
            voice.apply(control[f]);
            benchmark::DoNotOptimize(out.data());
        }
    }
    set_items(state, std::accumulate(counts.begin(), counts.end(), size_t{0}), "samples");
}
BENCHMARK(VoiceRender);

}  // namespace
}  // namespace tactus::bench
