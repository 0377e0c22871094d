// The engine as a live front end drives it, at 48 kHz in 64-frame blocks (a typical audio
// device's period), on the Amen break:
//   EngineBlock        each block's cost on the audio thread after one warm-up pass: p10, p50,
//                      p90, p99 and max in microseconds, against the block's period (1333 us at
//                      64 frames, 48 kHz). Run under SCHED_FIFO (chrt -f 80) for a fair max.
//   EngineBlock/routes:<r,r,...>  the same with the Amen break on two input channels and one
//                      actuator output per route (engine/route.hpp): four on `all` (one
//                      analysis, one synthesis) against four routes of every kind.
//   engine_block_layout/<name>  the same with a bundled layout's outputs (layouts/<name>.toml:
//                      routes, overlays, profiles, each output its own fit).
//   LiveChange/<key>   Engine::set() of a live parameter on the control thread (ns), with the
//                      audio thread taking the change at its next block.
//   StructuralSwap     Engine::set() of a structural parameter (the hop): a new pipeline built
//                      and primed with the input ring on the control thread (ms).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "bench_input.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/layout_file.hpp"

namespace tactus::bench {
namespace {

constexpr double kLiveRateHz = 48000;
constexpr int kLiveBlock = 64;
using Clock = std::chrono::steady_clock;

double microseconds(Clock::duration d) {
    return std::chrono::duration<double, std::micro>(d).count();
}

// Runs blocks of amen() through `engine` from `at` (wrapping), returns the next position.
size_t run_blocks(Engine& engine, size_t at, size_t blocks) {
    const std::vector<float>& in = amen();
    static std::vector<float> out(kLiveBlock);
    for (size_t b = 0; b < blocks; ++b) {
        if (at + kLiveBlock > in.size()) at = 0;
        engine.process(in.data() + at, out.data(), kLiveBlock);
        at += kLiveBlock;
    }
    return at;
}

// `routes`: none, one output on mono input (today's default); else one output per route, the
// input on two channels.
// `outputs` empty: the one default output, mono in; else those outputs, stereo in.
void engine_block_of(benchmark::State& state, const std::vector<ActuatorOutput>& outputs) {
    const std::vector<float>& in = amen();
    Engine engine;
    const int channels = outputs.empty() ? 1 : 2;
    if (!outputs.empty()) engine.set_actuators(outputs);
    engine.prepare({.sample_rate_hz = kLiveRateHz, .max_block = kLiveBlock, .channels = channels});
    std::vector<std::vector<float>> out(static_cast<size_t>(engine.actuators()),
                                        std::vector<float>(kLiveBlock));
    std::vector<float*> outs(out.size());
    for (size_t k = 0; k < out.size(); ++k) outs[k] = out[k].data();
    const auto process = [&](size_t i) {
        const float* ins[] = {in.data() + i, in.data() + i};
        engine.process(ins, outs.data(), kLiveBlock);
    };
    std::vector<double> us;
    us.reserve(in.size() / kLiveBlock * 64);
    for (size_t i = 0; i + kLiveBlock <= in.size(); i += kLiveBlock) process(i);  // warm
    for (auto _ : state) {
        for (size_t i = 0; i + kLiveBlock <= in.size(); i += kLiveBlock) {
            const auto start = Clock::now();
            process(i);
            us.push_back(microseconds(Clock::now() - start));
        }
        benchmark::DoNotOptimize(outs.data());
    }
    std::sort(us.begin(), us.end());
    state.counters["p10_us"] = us[us.size() / 10];
    state.counters["p50_us"] = us[us.size() / 2];
    state.counters["p90_us"] = us[us.size() * 9 / 10];
    state.counters["p99_us"] = us[us.size() * 99 / 100];
    state.counters["max_us"] = us.back();
    state.counters["period_us"] = kLiveBlock / kLiveRateHz * 1e6;
}

void engine_block(benchmark::State& state, const std::vector<std::string>& routes) {
    std::vector<ActuatorOutput> outputs(routes.size());
    for (size_t k = 0; k < routes.size(); ++k) outputs[k].route = Route::parse(routes[k]);
    engine_block_of(state, outputs);
}

// A bundled layout's outputs (layouts/NAME.toml): routes, overlays, profiles, trims, delays.
void engine_block_layout(benchmark::State& state, const std::string& name) {
    engine_block_of(state, load_layout(resolve_layout(name)).actuator_outputs([](const auto& a) {
        return load_actuator(resolve_actuator(a));
    }));
}

void EngineBlock(benchmark::State& state) {
    engine_block(state, {});
}
BENCHMARK(EngineBlock)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(engine_block, routes
                  : all x4, {"all", "all", "all", "all"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(engine_block, routes
                  : all kick + snare band : 40 - 200 channel : 2,
                    {"all", "kick+snare", "band:40-200", "channel:2"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(engine_block_layout, controller, "controller")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(engine_block_layout, column - 4, "column-4")->Unit(benchmark::kMillisecond);

// Turns `id` between two values, one turn per block; times set() alone.
void live_change(benchmark::State& state, P id, double a, double b) {
    Engine engine;
    engine.prepare(kLiveRateHz, kLiveBlock);
    size_t at = run_blocks(engine, 0, 100);
    bool flip = false;
    for (auto _ : state) {
        const auto start = Clock::now();
        engine.set(id, flip ? a : b);
        state.SetIterationTime(std::chrono::duration<double>(Clock::now() - start).count());
        at = run_blocks(engine, at, 1);
        flip = !flip;
    }
}
BENCHMARK_CAPTURE(live_change, envelope.decay_ms, P::envelope_decay_ms, 100, 200)->UseManualTime();
BENCHMARK_CAPTURE(live_change, post.drive_db, P::post_drive_db, 0, 6)->UseManualTime();
BENCHMARK_CAPTURE(live_change, post.flatten_level_db, P::post_flatten_level_db, 20, 30)
    ->UseManualTime();

// Turns the hop between 2 and 3 ms while audio runs; times set() alone, then runs the blocks
// that finish the crossfade (so the next set() frees the pipeline it replaced).
void StructuralSwap(benchmark::State& state) {
    Engine engine;
    engine.prepare(kLiveRateHz, kLiveBlock);
    const auto ring_blocks =
        static_cast<size_t>(Engine::kPrimeSeconds * kLiveRateHz / kLiveBlock) + 1;
    size_t at = run_blocks(engine, 0, ring_blocks);
    bool flip = false;
    for (auto _ : state) {
        const auto start = Clock::now();
        engine.set(P::analysis_hop_ms, flip ? 2.0 : 3.0);
        state.SetIterationTime(std::chrono::duration<double>(Clock::now() - start).count());
        at = run_blocks(engine, at, 20);
        flip = !flip;
    }
}
BENCHMARK(StructuralSwap)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tactus::bench
