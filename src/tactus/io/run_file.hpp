// Streams one audio file, or audio in memory (audio_source.hpp), in fixed blocks, through an
// Engine or through the analysis alone: the offline driver every command and the Python module
// share. Memory is constant in a file's length.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>

#include "tactus/dsp/process_spec.hpp"
#include "tactus/engine/channel_power.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_source.hpp"

namespace tactus {

// Frames stream_source reads and hands on at a time (large reads: fewer system calls).
inline constexpr int kStreamBlockFrames = Engine::kMaxBlock;

struct RunCallbacks {
    // Each block of vibration as it is produced, one buffer per actuator (may be empty;
    // run_source only).
    std::function<void(const float* const* vibration, int frames)> on_output{};
    // Frames done and the total (total <= 0 when unknown), about every 1 % of the file.
    std::function<void(int64_t done, int64_t total)> on_progress{};
    // Once the file is open and the engine or analyzer prepared, before any audio (may be
    // empty).
    std::function<void(double sample_rate_hz, int channels)> on_start{};
    // Each block of input just before the engine takes it, the tail's silence included (may be
    // empty; run_source only).
    std::function<void(const float* const* input, int frames)> on_input{};
};

struct RunSummary {
    double sample_rate_hz = 0;
    int input_channels = 0;
    int64_t frames = 0;           // input frames
    int64_t tail_frames = 0;      // silence fed after them (run_source with RunTail::ring_out)
    bool analysed_ahead = false;  // RunAnalysis::ahead, and it ran so
};

// What follows the input's last frame. ring_out feeds silence until the vibration has died
// away: a pulse triggered near the end of a short sound (a 19 ms tick, a 2 ms click) is
// rendered whole, not cut at the input's length.
enum class RunTail { none, ring_out };

// The tail: silence is fed until every output has stayed below kTailSilenceLevel (-80 dBFS,
// far below any felt level) for kTailSilenceS, and for at least the engine's latency; never
// more than kMaxTailS.
inline constexpr double kTailSilenceLevel = 1e-4;
inline constexpr double kTailSilenceS = 0.05;
inline constexpr double kMaxTailS = 10.0;

// Calls prepare(the source's sample rate and channel count, blocks of kStreamBlockFrames) (an
// std::invalid_argument becomes a std::runtime_error naming the source), then
// process(channels, frames) for every block to the end; a source without frames is an error.
// The driver under run_source and analyse_source.
using PrepareRun = std::function<void(const ProcessSpec& spec)>;
using ProcessRun = std::function<void(const float* const* channels, int frames)>;
RunSummary stream_source(AudioSource& source, const PrepareRun& prepare, const ProcessRun& process,
                         const RunCallbacks& callbacks = {});
// stream_source of the file `input`.
RunSummary stream_file(const std::filesystem::path& input, const PrepareRun& prepare,
                       const ProcessRun& process, const RunCallbacks& callbacks = {});

// Whether run_source prepares the engine at the source's rate and channel count (a command's
// engine), or takes it as prepared (a host's engine, running since before: its state kept; the
// source must have the rate it was prepared at, and the channel count).
enum class RunPrepare { engine, none };

// Where the engine's analysis runs: in Engine::process, or (an engine that has taken no input
// since it was prepared, on a machine of two cores or more, a source of kAheadMinS or more) on a
// thread of its own a few blocks ahead, the engine playing its frames back (io/analysis_ahead.hpp:
// the same output, bit for bit, in about two thirds of the time). After a run ahead the engine's
// own analysis has not heard the input: it is for an engine that ends with the run.
enum class RunAnalysis { engine, ahead };
// Shorter sources run in the engine: the second analysis's preparation and thread (about 0.4 M
// instructions) would cost more than they save.
inline constexpr double kAheadMinS = 0.5;

// Prepares `engine` at the source's sample rate and channel count (the engine downmixes),
// runs it to the end, then through the tail.
RunSummary run_source(AudioSource& source, Engine& engine, const RunCallbacks& callbacks = {},
                      RunTail tail = RunTail::none, RunPrepare prepare = RunPrepare::engine,
                      RunAnalysis analysis = RunAnalysis::engine);
// run_source of the file `input`.
RunSummary run_file(const std::filesystem::path& input, Engine& engine,
                    const RunCallbacks& callbacks = {}, RunTail tail = RunTail::none,
                    RunAnalysis analysis = RunAnalysis::engine);

// Prepares `analyzer` at the source's sample rate with `settings` and computes `features` (and
// the onsets) of the channels' mean, and calls on_frame for every analysis frame: the features
// of run_source's engine without its synthesis. Then BlockAnalysis::finish.
RunSummary analyse_source(AudioSource& source, Analyzer& analyzer, const Settings& settings,
                          FeatureSet features, const std::function<void(const Features&)>& on_frame,
                          const RunCallbacks& callbacks = {});
// analyse_source of the file `input`.
RunSummary analyse_file(const std::filesystem::path& input, Analyzer& analyzer,
                        const Settings& settings, FeatureSet features,
                        const std::function<void(const Features&)>& on_frame,
                        const RunCallbacks& callbacks = {});

// analyse_source's work on blocks of audio: the channels read as the engine reads them, their mean
// analysed and their loudness summed as BS.1770 sums it (engine/channel_power.hpp), or the one
// `input_channel` (Engine::set_input_channel). prepare() allocates and throws
// std::invalid_argument for a bad rate or setting; process() takes up to spec.max_block frames;
// finish() feeds silence for parts.settle_ms and one hop, so that the last onset's part and
// strength are decided, as a render's tail decides them.
class BlockAnalysis {
  public:
    using OnFrame = std::function<void(const Features&)>;
    explicit BlockAnalysis(Analyzer& analyzer) : analyzer_(analyzer) {}
    void prepare(const ProcessSpec& spec, const Settings& settings, FeatureSet features,
                 int input_channel = -1);
    void process(const float* const* channels, int frames, const OnFrame& on_frame);
    void finish(const OnFrame& on_frame);

  private:
    void analyse(const float* mono, const float* power, int frames, const OnFrame& on_frame);

    Analyzer& analyzer_;
    ChannelPower channel_power_;
    std::vector<float> mono_, power_;
    int channels_ = 1, input_channel_ = -1, max_block_ = 1;
    int64_t finish_frames_ = 0;
};

}  // namespace tactus
