// The whole pipeline of paper Figure 4 as one real-time processor, the engine every front end
// drives: audio -> analysis -> mapping -> synthesis -> post-processing -> N actuator outputs.
//
// Rates. Analysis runs at the input rate. Synthesis and post-processing run at an internal rate,
// the input rate divided by an integer, and each actuator's Upsampler brings its output back to
// the input rate. The vibration has nothing above the band's upper edge (<= 2 kHz), and
// synthesis samples one continuous-time signal (envelope and glides are exact at every sample
// instant, the phase integrates the glide exactly), so an internal rate of at least 11.025 kHz
// (5.5 times the highest edge) renders the same vibration as the input rate: eval/evaluate.py's
// pulse frequencies agree within 0.1 Hz at 44.1, 22.05 and 11.025 kHz.
//
// Channels. Any number of input channels, downmixed to their mean or one chosen channel; N
// actuator outputs (ActuatorOutput: profile, trim gain, delay), each with its own post chain,
// all reading one analysis and one synthesis.
//
// Threads (design.md, "One engine, many front ends"):
//   control threads  set(), set_actuator_gain_db(), inject(), trigger(): thread-safe among
//                    themselves; they validate, then hand the change to the audio thread
//                    through lock-free queues (moodycamel::ReaderWriterQueue). Live parameters
//                    glide over their smoothing time (LiveSettings); a flattening design is
//                    fitted here and glides in.
//   audio thread     process(): picks changes up at block boundaries; never allocates, locks,
//                    throws or does I/O; any block size (split at max_block).
//   one reader       pop_frame(): the analysis and vibration program of every frame.
//   setup            everything else (constructor, set_actuators, prepare, reset), while no
//                    other thread uses the engine.
// The vibration program (ControlFrame) is the seam: frames from the analysis, injected from
// outside, or both (ProgramSource), drive the synthesis.
#pragma once

#include <readerwriterqueue/readerwriterqueue.h>

#include <array>
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

#include "tactus/analysis/analyzer.hpp"
#include "tactus/engine/actuator_chain.hpp"
#include "tactus/engine/live_settings.hpp"
#include "tactus/engine/output_trim.hpp"
#include "tactus/mapping/mapper.hpp"
#include "tactus/params/params.hpp"
#include "tactus/synthesis/voice.hpp"

namespace tactus {

// What prepare() sizes the engine for.
struct EngineSpec {
    double sample_rate_hz = 48000;
    int max_block = 512;      // process() takes any count; it works in chunks of at most this
    int input_channels = 1;   // 1 ... kMaxInputChannels
    int input_channel = -1;   // the channel analysed; -1: the mean of all
};

// Where the synthesis takes its vibration program from.
enum class ProgramSource { analysis, external, both };

// One analysis frame and the control frame mapped from it, as pop_frame() delivers them.
struct AnalysisFrame {
    Features features;
    ControlFrame control;
};

// Receives every analysis frame and the control frame mapped from it, on the audio thread,
// inside process(): an implementation must itself be real-time safe when used live (a live
// reader uses pop_frame() instead).
class FrameObserver {
  public:
    virtual ~FrameObserver() = default;
    virtual void on_frame(const Features& features, const ControlFrame& control) noexcept = 0;
    // The features on_frame() reads besides the onsets (all by default); the engine computes
    // only these and what the mapping reads.
    virtual FeatureSet reads() const noexcept { return {}; }
};

class Engine {
  public:
    static constexpr double kMinSampleRateHz = 8000;
    static constexpr double kMaxSampleRateHz = 192000;
    static constexpr int kMaxBlock = 4096;
    static constexpr int kMaxInputChannels = 1024;  // libsndfile's SF_MAX_CHANNELS
    static constexpr int kMaxActuators = 64;
    static constexpr double kMinInternalRateHz = 11025;
    static constexpr int kQueueCapacity = 1024;  // changes or frames in flight per queue

    explicit Engine(Settings settings = {});

    // ---- setup ----
    // One actuator output (the CLI's default): none means no compensation. Its `dc` replaces
    // the actuator.dc setting, which gates the NPIII pressure.
    void set_actuator(std::optional<ActuatorProfile> actuator);
    // N actuator outputs; throws std::invalid_argument for a bad trim or delay, or none.
    void set_actuators(std::vector<ActuatorOutput> outputs);
    // Throws std::invalid_argument for a rate outside 8-192 kHz, a block outside 1-kMaxBlock or
    // channels outside their ranges. Allocates.
    void prepare(const EngineSpec& spec);
    void prepare(double sample_rate_hz, int max_block) {
        prepare({.sample_rate_hz = sample_rate_hz, .max_block = max_block});
    }
    static void check_sample_rate(double sample_rate_hz);
    void reset() noexcept;
    void set_observer(FrameObserver* observer);
    // Frames for pop_frame(), up to kQueueCapacity ahead of the reader (while it is that far
    // behind, new frames are dropped).
    void enable_frame_queue();

    // ---- audio thread ----
    // in: spec.input_channels channel pointers; out: actuators() channel pointers. Any count
    // (0 included). Inputs are read before outputs are written: they may alias.
    void process(const float* const* in, float* const* out, int count) noexcept;
    // Mono in, the first actuator out (may alias).
    void process(const float* in, float* out, int count) noexcept {
        process(&in, &out, count);
    }

    // ---- control threads ----
    // Validates (std::invalid_argument naming the key) and applies: before prepare to the
    // settings; after, a live parameter through the audio thread's queue. A structural one
    // after prepare throws std::logic_error: prepare() again.
    void set(P id, double value);
    void set_actuator_gain_db(int actuator, double gain_db);
    // The vibration program from outside: applied at the audio thread's next block.
    void inject(const ControlFrame& frame);
    // A pulse at `frequency_hz` and `amplitude` with the envelope of the current settings.
    void trigger(double frequency_hz, double amplitude);
    void set_program_source(ProgramSource source);
    // One reader thread: the oldest frame not yet read, if any.
    bool pop_frame(AnalysisFrame& frame);

    // ---- any thread, after prepare ----
    // The limiter's look-ahead plus the upsampler's delay, in samples at the input rate (each
    // actuator's own delay comes on top). The upsampler's delay is taken out of the look-ahead,
    // so this stays close to post.lookahead_ms.
    int latency() const;
    // Input samples per internal (synthesis and post-processing) sample.
    int rate_divisor() const { return rate_divisor_; }
    int actuators() const { return static_cast<int>(outputs_.size()); }
    // The settings as last set by a control thread.
    const Settings& settings() const { return settings_; }
    const EngineSpec& spec() const { return spec_; }
    double sample_rate_hz() const { return prepared_ ? spec_.sample_rate_hz : 0.0; }
    int hop_samples() const { return analyzer_.hop_samples(); }
    const PostChain& post(int actuator = 0) const {
        return chains_[static_cast<size_t>(chain_of_[static_cast<size_t>(actuator)])].post();
    }
    // Output samples a final clip at the ceiling changed (it should not: the limiter leaves a
    // margin), all actuators.
    int64_t clipped_samples() const;

  private:
    struct Change {  // control -> audio
        enum class Kind { parameter, actuator_gain, program_source } kind;
        int index;  // P, actuator or ProgramSource
        double value;
    };
    void process_chunk(const float* const* in, float* const* out, int offset,
                       int count) noexcept;
    void take_changes() noexcept;
    void apply_live() noexcept;
    void update_features() noexcept;
    const float* downmix(const float* const* in, int offset, int count) noexcept;
    void send(const Change& change);

    Settings settings_;                  // control side
    std::vector<ActuatorOutput> outputs_;
    EngineSpec spec_;
    int rate_divisor_ = 1;
    bool prepared_ = false;
    std::mutex control_;                 // control threads among themselves, never the audio thread

    // Audio side.
    LiveSettings live_;
    Analyzer analyzer_;
    Mapper mapper_;
    Voice voice_;
    std::vector<ActuatorChain> chains_;  // one per distinct profile
    std::vector<int> chain_of_;          // per actuator: its chain
    std::vector<int> first_of_chain_;    // per chain: the first actuator it feeds
    std::vector<OutputTrim> trims_;      // per actuator
    std::vector<float> mono_;             // downmixed input, one chunk
    std::vector<float> carrier_, flutter_, pressure_;  // synthesis, internal rate, one chunk
    bool flutter_on_ = false, pressure_on_ = false;
    int64_t position_ = 0;  // input samples consumed since reset
    ProgramSource source_ = ProgramSource::analysis;
    bool post_dirty_ = false;
    FrameObserver* observer_ = nullptr;

    moodycamel::ReaderWriterQueue<Change> changes_{kQueueCapacity};
    moodycamel::ReaderWriterQueue<ControlFrame> injected_{kQueueCapacity};
    moodycamel::ReaderWriterQueue<FlatteningFilter::Design> designs_{16};
    std::optional<moodycamel::ReaderWriterQueue<AnalysisFrame>> frames_;
};

}  // namespace tactus
