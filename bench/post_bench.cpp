// Each post-processing stage, the whole PostChain and the engine's upsampler, per sample, on the
// vibration the Voice makes for the Amen break (default settings), processed in 512-sample
// blocks. As in the engine, the stages run at its internal rate (11.025 kHz for the 44.1 kHz
// input).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "bench_input.hpp"
#include "tactus/core/units.hpp"
#include "tactus/dsp/upsampler.hpp"
#include "tactus/post/band_limit.hpp"
#include "tactus/post/flattening_filter.hpp"
#include "tactus/post/peak_limiter.hpp"
#include "tactus/post/post_chain.hpp"

namespace tactus::bench {
namespace {

constexpr int kBlock = 512;

// Copies the vibration block by block into a scratch buffer and lets `process` work on it.
template <typename Process>
void per_sample(benchmark::State& state, Process process) {
    const std::vector<float>& in = amen_vibration();
    std::vector<float> block(kBlock);
    for (auto _ : state) {
        for (size_t i = 0; i < in.size(); i += kBlock) {
            const int n = static_cast<int>(std::min<size_t>(kBlock, in.size() - i));
            std::copy_n(in.data() + i, n, block.data());
            process(block.data(), n);
            benchmark::DoNotOptimize(block.data());
        }
    }
    set_items(state, in.size(), "samples");
}

void BandLimitProcess(benchmark::State& state) {
    const Settings s;
    BandLimit band;
    band.prepare({.sample_rate_hz = internal_rate_hz()},
                 {.low_hz = s[P::post_band_low_hz],
                  .high_hz = s[P::post_band_high_hz],
                  .order = static_cast<int>(state.range(0))});
    per_sample(state, [&](float* x, int n) { band.process(x, n); });
}
BENCHMARK(BandLimitProcess)
    ->ArgName("order")
    ->Arg(PostChain::kFirstBandOrder)
    ->Arg(PostChain::kLastBandOrder);

void FlatteningProcess(benchmark::State& state) {
    const Settings s;
    FlatteningFilter flatten;
    flatten.prepare({.sample_rate_hz = internal_rate_hz()},
                    {.low_hz = s[P::post_band_low_hz],
                     .high_hz = s[P::post_band_high_hz],
                     .strength = s[P::post_flatten_strength],
                     .range_db = s[P::post_flatten_range_db]});
    per_sample(state, [&](float* x, int n) { flatten.process(x, n); });
}
BENCHMARK(FlatteningProcess);

void PeakLimiterProcess(benchmark::State& state) {
    const Settings s;
    PeakLimiter limiter;
    limiter.prepare({.sample_rate_hz = internal_rate_hz()}, s[P::post_lookahead_ms],
                    {.drive_db = s[P::post_drive_db],
                     .threshold_db = s[P::post_limiter_threshold_db],
                     .ceiling = db_to_gain(s[P::post_ceiling_db]),
                     .release_ms = s[P::post_release_ms]});
    per_sample(state, [&](float* x, int n) { limiter.process(x, n); });
}
BENCHMARK(PeakLimiterProcess);

void PostChainProcess(benchmark::State& state) {
    PostChain post;
    post.prepare({.sample_rate_hz = internal_rate_hz()}, Settings{});
    per_sample(state, [&](float* x, int n) { post.process(x, n); });
}
BENCHMARK(PostChainProcess);

// The engine's last stage: the vibration upsampled from the internal rate back to 44.1 kHz by
// the engine's factor. Items are internal samples in; each gives `factor` output samples.
void UpsamplerProcess(benchmark::State& state) {
    const int factor = rate_divisor();
    Upsampler upsampler;
    upsampler.prepare({.max_block = kBlock * factor}, factor);
    std::vector<float> out(static_cast<size_t>(kBlock * factor));
    per_sample(state, [&](float* x, int n) {
        upsampler.process(x, n, out.data(), n * factor);
        benchmark::DoNotOptimize(out.data());
    });
}
BENCHMARK(UpsamplerProcess);

}  // namespace
}  // namespace tactus::bench
