// File I/O, the part of `tactus render` around the pipeline: decoding the Amen break's FLAC
// through libsndfile (downmixed to mono, as render reads it) and writing its length of
// vibration as a float WAV. x real time as in WholePipeline; together they bound how fast
// render can be on a file, whatever the pipeline costs.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "bench_input.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/audio_writer.hpp"

namespace tactus::bench {
namespace {

void ReadFlac(benchmark::State& state) {
    size_t samples = 0;
    for (auto _ : state) {
        AudioReader reader(kAmenPath);
        ChannelBlock block(reader.channels(), Engine::kMaxBlock);
        samples = 0;
        while (const int got = reader.read(block.data(), Engine::kMaxBlock)) samples += got;
        benchmark::DoNotOptimize(block[0]);
    }
    set_real_time(state, samples);
}
BENCHMARK(ReadFlac)->Unit(benchmark::kMillisecond);

// The vibration render writes for the Amen break: the default Engine's output, at kRateHz
// (amen_vibration() is at the internal rate).
const std::vector<float>& amen_output() {
    static const std::vector<float> samples = [] {
        const std::vector<float>& in = amen();
        std::vector<float> out(in.size());
        Engine engine;
        engine.prepare(kRateHz, Engine::kMaxBlock);
        for (size_t i = 0; i < in.size(); i += Engine::kMaxBlock) {
            const int n = static_cast<int>(std::min<size_t>(Engine::kMaxBlock, in.size() - i));
            engine.process(in.data() + i, out.data() + i, n);
        }
        return out;
    }();
    return samples;
}

void WriteFloatWav(benchmark::State& state) {
    const std::vector<float>& vibration = amen_output();
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "tactus_bench_write.wav";
    for (auto _ : state) {
        AudioWriter writer(path, kRateHz, 1);
        for (size_t i = 0; i < vibration.size(); i += Engine::kMaxBlock) {
            const int n =
                static_cast<int>(std::min<size_t>(Engine::kMaxBlock, vibration.size() - i));
            writer.write(vibration.data() + i, n);
        }
        writer.commit();
    }
    std::filesystem::remove(path);
    set_real_time(state, vibration.size());
}
BENCHMARK(WriteFloatWav)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tactus::bench
