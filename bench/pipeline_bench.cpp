// Whole-pipeline throughput: the Amen break through Engine::process in 512-frame blocks, single
// thread. Reports x real time as a counter (audio seconds per wall second).
#include <benchmark/benchmark.h>

#include <vector>

#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"

namespace {

void WholePipeline(benchmark::State& state) {
    static const std::vector<float> input =
        tactus::read_mono("/usr/share/sonic-pi/samples/loop_amen_full.flac").samples;
    constexpr int kBlock = 512;
    tactus::Engine engine;
    engine.prepare(44100, kBlock);
    std::vector<float> out(kBlock);
    for (auto _ : state) {
        for (size_t i = 0; i + kBlock <= input.size(); i += kBlock)
            engine.process(input.data() + i, out.data(), kBlock);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["x_real_time"] =
        benchmark::Counter(static_cast<double>(input.size()) / 44100.0 * state.iterations(),
                           benchmark::Counter::kIsRate);
}
BENCHMARK(WholePipeline)->Unit(benchmark::kMillisecond);

}  // namespace
