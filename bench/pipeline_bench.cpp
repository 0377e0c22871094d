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
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(input.size()));
    state.counters["x_real_time"] =
        benchmark::Counter(static_cast<double>(input.size()) / kRateHz * state.iterations(),
                           benchmark::Counter::kIsRate);
}
BENCHMARK(WholePipeline)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tactus::bench
