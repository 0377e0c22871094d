// Whole-pipeline throughput: the Amen break through Engine::process in 512-frame blocks, single
// thread. Reports x real time as a counter (audio seconds per wall second).
#include <benchmark/benchmark.h>

#include <vector>

#include "bench_input.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus::bench {
namespace {

void WholePipeline(benchmark::State& state) {
    const std::vector<float>& input = amen();
    constexpr int kBlock = 512;
    Engine engine;
    engine.prepare(kRateHz, kBlock);
    std::vector<float> out(kBlock);
    for (auto _ : state) {
        for (size_t i = 0; i + kBlock <= input.size(); i += kBlock)
            engine.process(input.data() + i, out.data(), kBlock);
        benchmark::DoNotOptimize(out.data());
    }
    set_real_time(state, input.size());
}
BENCHMARK(WholePipeline)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tactus::bench
