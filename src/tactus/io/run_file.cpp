#include "tactus/io/run_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "tactus/dsp/denormals.hpp"
#include "tactus/dsp/downmix.hpp"
#include "tactus/io/analysis_ahead.hpp"

namespace tactus {
namespace {
constexpr int kBlock = kStreamBlockFrames;
}  // namespace

RunSummary stream_source(AudioSource& source, const PrepareRun& prepare, const ProcessRun& process,
                         const RunCallbacks& callbacks) {
    try {
        prepare({.sample_rate_hz = source.sample_rate_hz(),
                 .max_block = kStreamBlockFrames,
                 .channels = source.channels()});
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(fmt::format("{}: {}", source.name(), e.what()));
    }
    if (callbacks.on_start) callbacks.on_start(source.sample_rate_hz(), source.channels());
    RunSummary summary{source.sample_rate_hz(), source.channels(), 0};
    const int64_t report_every = std::max<int64_t>(kBlock, source.frames() / 100);
    int64_t next_report = 0;
    for (;;) {
        const float* const* in = nullptr;
        const int got = source.next(kBlock, in);
        if (got == 0) break;
        process(in, got);
        summary.frames += got;
        if (callbacks.on_progress && summary.frames >= next_report) {
            callbacks.on_progress(summary.frames, source.frames());
            next_report = summary.frames + report_every;
        }
    }
    if (summary.frames == 0)
        throw std::runtime_error(fmt::format("{}: no audio frames", source.name()));
    if (callbacks.on_progress) callbacks.on_progress(summary.frames, summary.frames);
    return summary;
}

RunSummary stream_file(const std::filesystem::path& input, const PrepareRun& prepare,
                       const ProcessRun& process, const RunCallbacks& callbacks) {
    FileSource source(input, kBlock);
    return stream_source(source, prepare, process, callbacks);
}

namespace {

using Run = AnalysisAhead::Run;

// Feeds the engine the tail (RunTail::ring_out) through `run`, which leaves each block's
// vibration in `out`; returns the frames fed. Ahead, the silence is given a few blocks before
// the engine runs it, and what is left once the vibration has rung out is not run.
int64_t run_tail(Engine& engine, int input_channels, AnalysisAhead* ahead, const Run& run,
                 const ChannelBlock& out) {
    const double rate_hz = engine.sample_rate_hz();
    const int block = std::max(1, static_cast<int>(rate_hz * 0.005));  // 5 ms
    const int64_t silent_needed = static_cast<int64_t>(std::ceil(kTailSilenceS * rate_hz));
    const int64_t min_frames = engine.latency();
    const int64_t max_frames = static_cast<int64_t>(kMaxTailS * rate_hz);
    ChannelBlock in(input_channels, block);
    for (int c = 0; c < input_channels; ++c) std::fill_n(in[c], block, 0.0f);
    int64_t fed = 0, silent = 0;
    const Run run_tail_block = [&](const float* const* input, int frames) {
        run(input, frames);
        fed += frames;
        float peak = 0.0f;
        for (int c = 0; c < engine.actuators(); ++c)
            for (int i = 0; i < frames; ++i) peak = std::max(peak, std::abs(out.data()[c][i]));
        silent = peak < kTailSilenceLevel ? silent + frames : 0;
    };
    while (fed < max_frames && (fed < min_frames || silent < silent_needed)) {
        if (!ahead) {
            run_tail_block(in.data(), block);
            continue;
        }
        while (ahead->queued() <= AnalysisAhead::kAhead) ahead->give(in.data(), block);
        ahead->run_oldest(run_tail_block);
    }
    return fed;
}

}  // namespace

RunSummary run_source(AudioSource& source, Engine& engine, const RunCallbacks& callbacks,
                      RunTail tail, RunPrepare prepare, RunAnalysis analysis) {
    std::optional<ChannelBlock> out;
    std::optional<AnalysisAhead> ahead;
    const Run run = [&](const float* const* in, int frames) {
        if (callbacks.on_input) callbacks.on_input(in, frames);
        engine.process(in, out->data(), frames);
        if (callbacks.on_output) callbacks.on_output(out->data(), frames);
    };
    RunSummary summary = stream_source(
        source,
        [&](const ProcessSpec& spec) {
            if (prepare == RunPrepare::engine)
                engine.prepare(spec);
            else if (spec.sample_rate_hz != engine.sample_rate_hz())
                throw std::invalid_argument(
                    fmt::format("sample rate {:g} Hz, the engine runs at {:g} Hz",
                                spec.sample_rate_hz, engine.sample_rate_hz()));
            out.emplace(engine.actuators(), kBlock);
            if (analysis == RunAnalysis::ahead && engine.position() == 0 && !engine.replaying() &&
                std::thread::hardware_concurrency() >= 2 &&
                !(source.frames() > 0 && source.frames() < kAheadMinS * spec.sample_rate_hz))
                ahead.emplace(engine, spec);
        },
        [&](const float* const* in, int frames) {
            if (!ahead) return run(in, frames);
            ahead->give(in, frames);
            if (ahead->queued() > AnalysisAhead::kAhead) ahead->run_oldest(run);
        },
        callbacks);
    while (ahead && ahead->queued() > 0) ahead->run_oldest(run);
    summary.analysed_ahead = ahead.has_value();
    if (tail == RunTail::ring_out)
        summary.tail_frames =
            run_tail(engine, summary.input_channels, ahead ? &*ahead : nullptr, run, *out);
    return summary;
}

RunSummary run_file(const std::filesystem::path& input, Engine& engine,
                    const RunCallbacks& callbacks, RunTail tail, RunAnalysis analysis) {
    FileSource source(input, kBlock);
    return run_source(source, engine, callbacks, tail, RunPrepare::engine, analysis);
}

void BlockAnalysis::prepare(const ProcessSpec& spec, const Settings& settings, FeatureSet features,
                            int input_channel) {
    Engine::check_sample_rate(spec.sample_rate_hz);
    analyzer_.prepare(spec, settings);
    analyzer_.set_features(features);
    channels_ = spec.channels;
    input_channel_ = input_channel;
    max_block_ = spec.max_block;
    mono_.assign(static_cast<size_t>(max_block_), 0.0f);
    power_.assign(channels_ > 1 ? mono_.size() : 0, 0.0f);
    if (channels_ > 1) channel_power_.prepare(spec);
    finish_frames_ = ms_to_samples(settings[P::parts_settle_ms], spec.sample_rate_hz) +
                     static_cast<int64_t>(std::ceil(analyzer_.hop_samples()));
}

void BlockAnalysis::process(const float* const* channels, int frames, const OnFrame& on_frame) {
    const ScopedFlushDenormals no_denormals;  // as in Engine::process
    if (channels_ == 1) return analyse(channels[0], nullptr, frames, on_frame);
    if (input_channel_ >= 0) return analyse(channels[input_channel_], nullptr, frames, on_frame);
    downmix_mean(channels, channels_, 0, mono_.data(), frames);  // the engine's default downmix
    channel_power_.process(channels, 0, frames, power_.data());
    analyse(mono_.data(), power_.data(), frames, on_frame);
}

void BlockAnalysis::finish(const OnFrame& on_frame) {
    std::vector<float> silence(static_cast<size_t>(max_block_), 0.0f);
    std::vector<const float*> channels(static_cast<size_t>(channels_), silence.data());
    for (int64_t left = finish_frames_; left > 0;) {
        const int frames = static_cast<int>(std::min<int64_t>(left, max_block_));
        process(channels.data(), frames, on_frame);
        left -= frames;
    }
}

void BlockAnalysis::analyse(const float* mono, const float* power, int frames,
                            const OnFrame& on_frame) {
    for (int done = 0; done < frames;) {
        const int chunk = std::min(frames - done, analyzer_.samples_to_next_frame());
        if (analyzer_.process(mono + done, power ? power + done : nullptr, chunk))
            on_frame(analyzer_.analyse());
        done += chunk;
    }
}

RunSummary analyse_source(AudioSource& source, Analyzer& analyzer, const Settings& settings,
                          FeatureSet features, const std::function<void(const Features&)>& on_frame,
                          const RunCallbacks& callbacks) {
    BlockAnalysis analysis(analyzer);
    const RunSummary summary = stream_source(
        source, [&](const ProcessSpec& spec) { analysis.prepare(spec, settings, features); },
        [&](const float* const* channels, int frames) {
            analysis.process(channels, frames, on_frame);
        },
        callbacks);
    analysis.finish(on_frame);
    return summary;
}

RunSummary analyse_file(const std::filesystem::path& input, Analyzer& analyzer,
                        const Settings& settings, FeatureSet features,
                        const std::function<void(const Features&)>& on_frame,
                        const RunCallbacks& callbacks) {
    FileSource source(input, kBlock);
    return analyse_source(source, analyzer, settings, features, on_frame, callbacks);
}

}  // namespace tactus
