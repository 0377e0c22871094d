// What starting the engine costs, for `make bench-instructions` (bench/instructions.sh runs it
// under callgrind, counting inside the measured_* functions alone, and on its own for times):
//   startup_bench prepare   the first Engine::prepare in the process (FFT plans, fits), then
//                           another engine's with the same settings (what a Python Engine, a
//                           Pd `prepare` or a new pipeline pays once the process has started)
//   startup_bench process S [B]  Engine::process on S seconds of the Amen break at 48 kHz mono
//                           (the default preset, B-frame blocks, 512 unless given)
//   startup_bench blocks S  Engine::process on S seconds of the Amen break at 48 kHz mono in
//                           64-frame blocks (a live device's period) after a second's warm-up,
//                           each block a call of its own: instructions per block
//   startup_bench floor     nothing: the dynamic loader and the libraries' start-up alone, the
//                           least any program linked as the engine pays
//   startup_bench fftw      FFTW's first plan, of 2 points: its planner made (its solvers
//                           registered), the least the first FFT plan of a process pays
//   startup_bench swap N    N structural changes (the hop, 2 <-> 3 ms) on the control thread of
//                           an engine running at 48 kHz in 64-frame blocks: prints the median
//                           and largest time of Engine::set() in ms
#include <fftw3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <vector>

#include "tactus/dsp/resampler.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"

namespace {

using tactus::Engine;
constexpr double kRateHz = 48000;
constexpr const char* kAmenPath = "/usr/share/sonic-pi/samples/loop_amen_full.flac";

// The Amen break, mono, converted to 48 kHz by the listening resampler, looped to `seconds`.
std::vector<float> amen_48k(double seconds) {
    const tactus::MonoAudio amen = tactus::read_mono(kAmenPath);
    const auto count = static_cast<int>(amen.samples.size());
    tactus::Resampler resampler;
    resampler.prepare(amen.sample_rate_hz, kRateHz, count, tactus::Resampler::Band::listening);
    std::vector<float> once(static_cast<size_t>(count) * 2);
    once.resize(static_cast<size_t>(resampler.process(amen.samples.data(), count, once.data())));
    std::vector<float> out(static_cast<size_t>(seconds * kRateHz));
    for (size_t i = 0; i < out.size(); ++i) out[i] = once[i % once.size()];
    return out;
}

void run(Engine& engine, std::span<const float> in, int block) {
    std::vector<float> out(static_cast<size_t>(block));
    for (size_t at = 0; at + static_cast<size_t>(block) <= in.size(); at += block)
        engine.process(in.data() + at, out.data(), block);
}

}  // namespace

// Counted by name (callgrind --toggle-collect): kept out of line.
extern "C" {
__attribute__((noinline)) void measured_first_prepare(Engine& engine) {
    engine.prepare(kRateHz, 512);
}
__attribute__((noinline)) void measured_prepare_again(Engine& engine) {
    engine.prepare(kRateHz, 512);
}
__attribute__((noinline)) void measured_process(Engine& engine, const std::vector<float>& in,
                                                int block) {
    run(engine, in, block);
}
__attribute__((noinline)) void measured_block(Engine& engine, const float* in, float* out,
                                              int block) {
    engine.process(in, out, block);
}
__attribute__((noinline)) void measured_fftw_planner() {
    float time[2] = {};
    fftwf_complex spectrum[2] = {};
    fftwf_destroy_plan(fftwf_plan_dft_r2c_1d(2, time, spectrum, FFTW_ESTIMATE));
}
__attribute__((noinline)) void measured_swap(Engine& engine, double hop_ms) {
    engine.set(tactus::P::analysis_hop_ms, hop_ms);
}
}

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "floor") return 0;
    if (mode == "fftw") {
        measured_fftw_planner();
        return 0;
    }
    if (mode == "prepare") {
        Engine first, again;
        measured_first_prepare(first);
        measured_prepare_again(again);
        return 0;
    }
    if (mode == "process" && argc > 2) {
        const std::vector<float> in = amen_48k(std::atof(argv[2]));
        const int block = argc > 3 ? std::atoi(argv[3]) : 512;
        Engine engine;
        engine.prepare(kRateHz, block);
        measured_process(engine, in, block);
        return 0;
    }
    if (mode == "blocks" && argc > 2) {
        constexpr int kBlock = 64;
        constexpr double kWarmUpS = 1.0;  // the analysis's history and the onset median filled
        const std::vector<float> in = amen_48k(kWarmUpS + std::atof(argv[2]));
        const auto warm_up = static_cast<size_t>(kWarmUpS * kRateHz);
        Engine engine;
        engine.prepare(kRateHz, kBlock);
        run(engine, std::span(in).first(warm_up), kBlock);
        std::vector<float> out(kBlock);
        for (size_t at = warm_up; at + kBlock <= in.size(); at += kBlock)
            measured_block(engine, in.data() + at, out.data(), kBlock);
        return 0;
    }
    if (mode == "swap" && argc > 2) {
        const int swaps = std::max(1, std::atoi(argv[2]));
        constexpr int kBlock = 64;
        const std::vector<float> in = amen_48k(Engine::kPrimeSeconds + 0.5);
        const auto between = std::span(in).first(20 * size_t{kBlock});
        Engine engine;
        engine.prepare(kRateHz, kBlock);
        run(engine, in, kBlock);  // the input ring full, as in a running engine
        std::vector<double> ms;
        for (int i = 0; i < swaps; ++i) {
            const auto start = std::chrono::steady_clock::now();
            measured_swap(engine, i % 2 == 0 ? 3.0 : 2.0);
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
            run(engine, between, kBlock);  // the crossfade done: the old pipeline comes back
        }
        std::sort(ms.begin(), ms.end());
        std::printf("%.2f %.2f\n", ms[ms.size() / 2], ms.back());
        return 0;
    }
    std::fprintf(
        stderr,
        "usage: %s floor | fftw | prepare | process SECONDS | blocks SECONDS | swap COUNT\n",
        argv[0]);
    return 2;
}
