// Streams one audio file in fixed blocks, through an Engine or through the analysis alone: the
// offline driver every command shares. Memory is constant in the file's length.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>

#include "tactus/dsp/process_spec.hpp"
#include "tactus/engine/channel_power.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus {

// Frames stream_file reads and hands on at a time (large reads: fewer system calls).
inline constexpr int kStreamBlockFrames = Engine::kMaxBlock;

struct RunCallbacks {
    // Each block of vibration as it is produced, one buffer per actuator (may be empty;
    // run_file only).
    std::function<void(const float* const* vibration, int frames)> on_output{};
    // Frames done and the total (total <= 0 when unknown), about every 1 % of the file.
    std::function<void(int64_t done, int64_t total)> on_progress{};
    // Once the file is open and the engine or analyzer prepared, before any audio (may be
    // empty).
    std::function<void(double sample_rate_hz, int channels)> on_start{};
};

struct RunSummary {
    double sample_rate_hz = 0;
    int input_channels = 0;
    int64_t frames = 0;       // input frames
    int64_t tail_frames = 0;  // silence fed after them (run_file with RunTail::ring_out)
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

// Feeds `engine` (prepared, input_channels wide) the tail, handing every block to on_output;
// returns the frames fed.
int64_t run_tail(Engine& engine, int input_channels,
                 const std::function<void(const float* const* vibration, int frames)>& on_output);

// Opens `input`, calls prepare(its sample rate and channel count, blocks of
// kStreamBlockFrames) (an std::invalid_argument becomes a std::runtime_error naming the file),
// then process(channels, frames) for every block to the end; a file without frames is an
// error. The driver under run_file and analyse_file.
RunSummary stream_file(const std::filesystem::path& input,
                       const std::function<void(const ProcessSpec& spec)>& prepare,
                       const std::function<void(const float* const* channels, int frames)>& process,
                       const RunCallbacks& callbacks = {});

// Opens `input`, prepares `engine` at the file's sample rate and channel count (the engine
// downmixes), runs it to the end, then through the tail.
RunSummary run_file(const std::filesystem::path& input, Engine& engine,
                    const RunCallbacks& callbacks = {}, RunTail tail = RunTail::none);

// Opens `input`, prepares `analyzer` at the file's sample rate with `settings` and computes
// `features` (and the onsets) of the channels' mean, and calls on_frame for every analysis
// frame: the features of run_file's engine without its synthesis.
RunSummary analyse_file(const std::filesystem::path& input, Analyzer& analyzer,
                        const Settings& settings, FeatureSet features,
                        const std::function<void(const Features&)>& on_frame,
                        const RunCallbacks& callbacks = {});

// analyse_file's work on blocks of audio (also the Python module's onsets(), on audio in
// memory): the channels read as the engine reads them, their mean analysed and their loudness
// summed as BS.1770 sums it (engine/channel_power.hpp). prepare() allocates and throws
// std::invalid_argument for a bad rate or setting; process() takes up to spec.max_block frames;
// finish() feeds silence for parts.settle_ms and one hop, so that the last onset's part and
// strength are decided, as a render's tail decides them.
class BlockAnalysis {
  public:
    using OnFrame = std::function<void(const Features&)>;
    explicit BlockAnalysis(Analyzer& analyzer) : analyzer_(analyzer) {}
    void prepare(const ProcessSpec& spec, const Settings& settings, FeatureSet features);
    void process(const float* const* channels, int frames, const OnFrame& on_frame);
    void finish(const OnFrame& on_frame);

  private:
    void analyse(const float* mono, const float* power, int frames, const OnFrame& on_frame);

    Analyzer& analyzer_;
    ChannelPower channel_power_;
    std::vector<float> mono_, power_;
    int channels_ = 1, max_block_ = 1;
    int64_t finish_frames_ = 0;
};

}  // namespace tactus
