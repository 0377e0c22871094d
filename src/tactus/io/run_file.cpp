#include "tactus/io/run_file.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <vector>

#include "tactus/io/audio_reader.hpp"

namespace tactus {

RunSummary run_file(const std::filesystem::path& input, Engine& engine,
                    const RunCallbacks& callbacks) {
    constexpr int kBlock = Engine::kMaxBlock;  // large reads: fewer system calls
    AudioReader reader(input);
    try {
        engine.prepare(reader.sample_rate_hz(), kBlock);
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(fmt::format("{}: {}", input.string(), e.what()));
    }
    if (callbacks.on_start) callbacks.on_start(reader.sample_rate_hz(), reader.channels());
    std::vector<float> in(kBlock), out(kBlock);
    RunSummary summary{reader.sample_rate_hz(), reader.channels(), 0};
    const int64_t report_every = std::max<int64_t>(kBlock, reader.frames() / 100);
    int64_t next_report = 0;
    for (;;) {
        const int got = reader.read(in.data(), kBlock);
        if (got == 0) break;
        engine.process(in.data(), out.data(), got);
        if (callbacks.on_output) callbacks.on_output(out.data(), got);
        summary.frames += got;
        if (callbacks.on_progress && summary.frames >= next_report) {
            callbacks.on_progress(summary.frames, reader.frames());
            next_report = summary.frames + report_every;
        }
    }
    if (summary.frames == 0)
        throw std::runtime_error(fmt::format("{}: no audio frames", input.string()));
    if (callbacks.on_progress) callbacks.on_progress(summary.frames, summary.frames);
    return summary;
}

}  // namespace tactus
