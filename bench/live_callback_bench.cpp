// The audio callback of `tactus live` (apps/tactus/live/live_callback.hpp) at 48 kHz in 64-frame
// blocks, on the Amen break, as a device calls it: each block's cost after one warm-up pass,
// p50, p99 and max in microseconds against the block's period (1333 us). Run under SCHED_FIFO
// (chrt -f 80) for a fair max.
//   LiveCallbackInput   an instrument's input (one device channel) -> one actuator channel
//   LiveCallbackPlayer  the player: the file's sound to two channels held back by --sync, the
//                       vibration to two actuator channels
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <vector>

#include "bench_input.hpp"
#include "live/live_callback.hpp"
#include "tactus/io/audio_writer.hpp"

namespace tactus::bench {
namespace {

constexpr double kLiveRateHz = 48000;
constexpr int kLiveBlock = 64;
using Clock = std::chrono::steady_clock;

// Times every block of `blocks` calls after a warm-up pass; sets the counters.
template <typename Block>
void time_blocks(benchmark::State& state, size_t blocks, Block&& block) {
    std::vector<double> us;
    us.reserve(blocks * 64);
    for (size_t b = 0; b < blocks; ++b) block(b);
    for (auto _ : state)
        for (size_t b = 0; b < blocks; ++b) {
            const auto start = Clock::now();
            block(b);
            us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
        }
    std::sort(us.begin(), us.end());
    state.counters["p50_us"] = us[us.size() / 2];
    state.counters["p99_us"] = us[us.size() * 99 / 100];
    state.counters["max_us"] = us.back();
    state.counters["period_us"] = kLiveBlock / kLiveRateHz * 1e6;
}

void LiveCallbackInput(benchmark::State& state) {
    const std::vector<float>& in = amen();
    Engine engine;
    engine.prepare({.sample_rate_hz = kLiveRateHz, .max_block = kLiveBlock, .channels = 1});
    live::LiveCallback callback(
        engine, nullptr,
        {.device_inputs = 1, .device_outputs = 1, .actuator_channels = {0}, .sound_channels = {}},
        0);
    callback.begin();
    std::vector<float> out(kLiveBlock);
    time_blocks(state, in.size() / kLiveBlock, [&](size_t b) {
        callback.process(in.data() + b * kLiveBlock, out.data(), kLiveBlock);
    });
    benchmark::DoNotOptimize(out.data());
}
BENCHMARK(LiveCallbackInput)->Unit(benchmark::kMillisecond);

void LiveCallbackPlayer(benchmark::State& state) {
    const std::vector<float>& amen_samples = amen();
    const auto file = std::filesystem::temp_directory_path() / "tactus_live_bench.wav";
    {
        AudioWriter writer(file, kLiveRateHz, 1);
        const float* channel = amen_samples.data();
        writer.write(&channel, static_cast<int>(amen_samples.size()));
        writer.commit();
    }
    live::Player player({file}, kLiveRateHz, /*loop=*/true);
    std::filesystem::remove(file);
    Engine engine;
    engine.set_actuators({ActuatorOutput{}, ActuatorOutput{}});
    engine.prepare({.sample_rate_hz = kLiveRateHz, .max_block = kLiveBlock, .channels = 1});
    live::LiveCallback callback(engine, &player,
                                {.device_inputs = 0,
                                 .device_outputs = 4,
                                 .actuator_channels = {0, 1},
                                 .sound_channels = {2, 3}},
                                196);
    callback.begin();
    std::vector<float> out(4 * static_cast<size_t>(kLiveBlock));
    time_blocks(state, amen_samples.size() / kLiveBlock,
                [&](size_t) { callback.process(nullptr, out.data(), kLiveBlock); });
    benchmark::DoNotOptimize(out.data());
}
BENCHMARK(LiveCallbackPlayer)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tactus::bench
