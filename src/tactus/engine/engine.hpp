// The whole pipeline of paper Figure 4 as one real-time processor, the engine every front end
// drives: audio -> analysis -> mapping -> synthesis -> post-processing -> N actuator outputs.
//
// Rates. Analysis runs at one analysis rate, 16 kHz, whatever the input rate (Analyzer: a
// minimum-phase polyphase resampler in front of it, so windows and hops are the same number of
// analysis samples and the spectrum ends at the same frequency at every input rate; loudness
// is K-weighted at the input rate, as BS.1770 specifies it for any rate). Frames end at whole
// input samples (hop_samples() is their mean spacing); onset times map back to input samples
// exactly, less the resampler's constant delay (about 0.2 ms). Between 16 and 192 kHz the same
// music gives the same onsets within 1 ms and the same pulses (eval/sample_rates.py). Synthesis
// and post-processing run at an internal rate, the input rate divided by an integer, and each
// actuator chain's Upsampler brings its output back to the input rate. The vibration has
// nothing above the band's upper edge (<= 2 kHz), and synthesis samples one continuous-time
// signal (envelope and glides are exact at every sample instant, the phase integrates the glide
// exactly), so an internal rate of at least 11.025 kHz (5.5 times the highest edge) renders the
// same vibration as the input rate.
//
// Channels. Any number of input channels, downmixed to their mean or one chosen channel (the
// mean's loudness is the channels' sum as ITU-R BS.1770 sums it: engine/channel_power.hpp); N
// actuator outputs (ActuatorOutput: profile, trim gain, delay, route), each playing its route
// (engine/route.hpp): one analysis per distinct input a route hears, one synthesis per distinct
// way of playing it, one post chain per distinct profile among its outputs (Pipeline).
//
// Threads (docs/architecture.md, "Threads and queues"):
//   control threads  set(), set_actuator_gain_db(), set_outputs(), set_route(), inject(),
//                    trigger(), set_program_source(), settings_snapshot(), settings():
//                    thread-safe among themselves (a mutex no audio thread takes); they validate,
//                    then hand the change to the audio thread through a lock-free queue
//                    (moodycamel::ReaderWriterQueue). A live parameter glides over its smoothing
//                    time (LiveSettings); a flattening design is fitted here and glides in. A
//                    structural one builds a new Pipeline here, primes it with the last seconds
//                    of input (InputRing: its onset history, loudness and envelopes are those of
//                    the running one), and the audio thread catches it up and crossfades to it
//                    over kCrossfadeMs: no gap, no lost onset. Pipelines the audio thread is done
//                    with come back to be freed here.
//   audio thread     process(): picks changes up at block boundaries; never allocates, frees,
//                    locks, throws or does I/O; any block size (split at max_block).
//   one reader       pop_frame(), pop_lane_frame(): the analysis and vibration program of every
//                    frame, and what each lane plays of it.
//   setup            everything else (constructor, set_actuators, set_observer,
//                    enable_frame_queue, prepare, reset, post()), while no other thread uses it.
// The vibration program (ControlFrame) is the seam: frames from the analysis, injected from
// outside, or both (ProgramSource), drive the synthesis.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <type_traits>
#include <vector>

#include "tactus/engine/channel_power.hpp"
#include "tactus/engine/input_ring.hpp"
#include "tactus/engine/output_trim.hpp"
#include "tactus/engine/pipeline.hpp"
#include "tactus/engine/settings_snapshot.hpp"
#include "tactus/engine/spsc_queue.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

// One analysis frame and the control frame mapped from it, as pop_frame() delivers them.
struct AnalysisFrame {
    Features features;
    ControlFrame control;
};

// One frame of a lane's vibration program (FrameObserver::on_lane_frame), as pop_lane_frame()
// delivers them.
struct LaneFrame {
    int lane = 0;
    ControlFrame control;
};

class Engine {
  public:
    static constexpr double kMinSampleRateHz = 8000;
    static constexpr double kMaxSampleRateHz = 192000;
    static constexpr int kMaxBlock = 4096;
    static constexpr int kMaxInputChannels = 1024;  // libsndfile's SF_MAX_CHANNELS
    static constexpr int kMaxActuators = 64;
    static constexpr double kMinInternalRateHz = Pipeline::kMinInternalRateHz;
    static constexpr int kQueueCapacity = 1024;   // frames or injected frames in flight
    static constexpr int kChangeCapacity = 256;   // changes in flight
    static constexpr double kCrossfadeMs = 10;    // a structural change's handover
    static constexpr double kPrimeSeconds = 2.5;  // the most input a new pipeline hears
                                                  // before it plays (prime_seconds())
    static constexpr int kPrimeBlock = 1024;      // samples a new pipeline is primed with at a time

    // The input a new pipeline for `settings` hears before it plays, so its state is the
    // running one's: the longest its stages remember, at most kPrimeSeconds. Any thread.
    static double prime_seconds(const Settings& settings);

    explicit Engine(Settings settings = {});
    ~Engine();
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // ---- setup ----
    // One actuator output (the CLI's default): none means no compensation. Its `dc` replaces
    // the actuator.dc setting, which gates the NPIII pressure, and the pipeline runs the
    // settings fitted to its profile (actuator/fit.hpp: band, flutter, pressure; settings()
    // stays as set). With several outputs the first one's profile decides the pressure, and
    // each output plays the settings fitted to its own profile (as_played()).
    void set_actuator(std::optional<ActuatorProfile> actuator);
    // N actuator outputs; throws std::invalid_argument for a bad trim or delay, or none.
    void set_actuators(std::vector<ActuatorOutput> outputs);
    // The input channel analysed; -1 (the default): the mean of all.
    void set_input_channel(int channel) { input_channel_ = channel; }
    // spec.channels: input channels (1 ... kMaxInputChannels); process() takes any count and
    // works in chunks of at most spec.max_block. Throws std::invalid_argument for a rate
    // outside 8-192 kHz, a block outside 1-kMaxBlock, channels or the input channel outside
    // their ranges. Allocates.
    void prepare(const ProcessSpec& spec);
    void prepare(double sample_rate_hz, int max_block) {
        prepare({.sample_rate_hz = sample_rate_hz, .max_block = max_block});
    }
    static void check_sample_rate(double sample_rate_hz);
    void reset() noexcept;
    void set_observer(FrameObserver* observer);
    // Plays `recording` (recorded_analysis.hpp: this input's frames, recorded by an engine with
    // the same values of the parameters Analyzer::reads()) back in place of the analysis: the
    // input is then only passed through, the vibration is the one analysing it would give, bit
    // for bit, without the analysis's cost. Null: analyses the input again. The caller keeps the
    // analysis parameters as recorded (they are not checked).
    void replay_analysis(std::shared_ptr<const RecordedAnalysis> recording);
    // Setup thread: whether the input went on past the recording's last frame (the vibration
    // after it followed no analysis: render again, analysing).
    bool replay_ran_out() const { return active_ && active_->replay_ran_out(); }
    // Setup thread: whether a recording plays back in place of the analysis.
    bool replaying() const { return recording_ != nullptr; }
    // Setup thread: the input samples the running pipeline has taken since prepare() or reset().
    int64_t position() const { return active_ ? active_->position() : 0; }
    // Setup, prepared: what the running pipeline's analysis reads. BlockAnalysis
    // (io/run_file.hpp) prepared with these at the engine's spec gives the frames that analysis
    // would, bit for bit, for playing back (io/analysis_ahead.hpp).
    struct AnalysisSetup {
        Settings settings;  // fitted to the actuator, as the pipeline runs them
        FeatureSet features;
        int input_channel = -1;
    };
    AnalysisSetup analysis_setup() const {
        return {fitted(settings_), active_->analysed_features(), input_channel_};
    }
    // Frames for pop_frame(), up to kQueueCapacity ahead of the reader (while it is that far
    // behind, new frames are dropped).
    void enable_frame_queue();

    // ---- audio thread ----
    // in: spec.input_channels channel pointers; out: actuators() channel pointers. Any count
    // (0 included). Inputs are read before outputs are written: they may alias.
    void process(const float* const* in, float* const* out, int count) noexcept;
    // Mono in, the first actuator out (may alias).
    void process(const float* in, float* out, int count) noexcept { process(&in, &out, count); }

    // ---- control threads ----
    // Validates (std::invalid_argument naming the key) and applies: before prepare to the
    // settings; after, through the audio thread (live: gliding; structural: swapped in). A value
    // it already has changes nothing. When the queue to the audio thread has no room for every
    // change it makes, throws std::runtime_error having changed nothing.
    void set(P id, double value);
    // Every parameter at once (a preset, a restored state): the structural ones that differ
    // build one new pipeline between them, not one each.
    void set(const Settings& settings);
    void set_actuator_gain_db(int actuator, double gain_db);
    // One actuator's route (engine/route.hpp), the rest of its output and the others kept, as
    // set_outputs() changes them.
    void set_route(int actuator, const Route& route);
    // Every actuator output at once (a layout): routes, overlays and profiles swapped in without
    // a gap (one pipeline), trims gliding. As many as there are actuators; a delay is the
    // engine's setup, so after prepare a changed one throws std::invalid_argument, as does a bad
    // output (a channel the input lacks, a bad overlay: naming the actuator), having changed
    // nothing. Before prepare, set_actuators().
    void set_outputs(std::vector<ActuatorOutput> outputs);
    std::vector<ActuatorOutput> outputs() const;
    // The vibration program from outside: applied at the audio thread's next block.
    void inject(const ControlFrame& frame);
    // A pulse at `frequency_hz` and `amplitude` with the envelope of the current settings.
    void trigger(double frequency_hz, double amplitude);
    // What trigger() accepts: throws std::invalid_argument naming the values (any thread).
    static void check_trigger(double frequency_hz, double amplitude);
    void set_program_source(ProgramSource source);
    // One reader thread: the oldest frame not yet read, if any.
    bool pop_frame(AnalysisFrame& frame);
    // The same reader: the oldest lane frame not yet read (enable_frame_queue()), if any.
    bool pop_lane_frame(LaneFrame& frame);
    // The settings as last set, whole, and their version (settings_snapshot.hpp). Takes the
    // control mutex: never from the audio thread.
    SettingsSnapshot settings_snapshot() const;
    // settings_snapshot().settings: a copy, safe while another control thread calls set().
    Settings settings() const { return settings_snapshot().settings; }

    // ---- any thread, after prepare ----
    // The limiter's look-ahead plus the upsampler's delay, in samples at the input rate (each
    // actuator's own delay comes on top). The upsampler's delay is taken out of the look-ahead,
    // so this stays close to post.lookahead_ms.
    int latency() const { return latency_.load(std::memory_order_relaxed); }
    // Input samples per analysis frame, on average: the analysis hop is a whole number of
    // samples at the analysis rate (Analyzer), frames end at whole input samples.
    double hop_samples() const { return hop_samples_.load(std::memory_order_relaxed); }
    // Input samples per internal (synthesis and post-processing) sample.
    int rate_divisor() const { return rate_divisor_; }
    int actuators() const { return static_cast<int>(outputs_.size()); }
    double sample_rate_hz() const { return prepared_ ? spec_.sample_rate_hz : 0.0; }
    // Setup thread: the lane of the running pipeline an actuator plays (pop_lane_frame()), and
    // how many lanes it has (outputs on the same route and overlay share one).
    int lane_of(int actuator) const { return active_->lane_of(actuator); }
    int lanes() const { return active_->lanes(); }
    // Setup thread: the running pipeline's post chain for an actuator.
    const PostChain& post(int actuator = 0) const { return active_->post(actuator); }
    // Output samples a final clip at the ceiling changed (it should not: the limiter leaves a
    // margin), all actuators. Setup thread.
    int64_t clipped_samples() const { return active_ ? active_->clipped_samples() : 0; }

  private:
    // One change from a control thread to the audio thread, in the order made. Each kind has
    // its own fields; the queue copies it as bytes, never allocating.
    struct Change {
        enum class Kind { parameter, flattening, actuator_gain, program_source, pipeline } kind;
        P param{};                          // parameter, flattening: which one
        double value = 0;                   // parameter, flattening: its new value
        FlatteningFilter::Design design{};  // flattening: for the pipeline running then
        int actuator = 0;                   // actuator_gain: which one
        double gain_db = 0;                 // actuator_gain: its new gain
        ProgramSource source{};             // program_source: what drives the vibration
        Pipeline* pipeline = nullptr;       // pipeline: a structural change, primed up to
        int64_t primed_to = 0;              // `primed_to`
    };
    static_assert(std::is_trivially_copyable_v<Change>);

    // Forwards the running pipeline's frames to the observer and the frame queue.
    class FrameForwarder : public FrameObserver {
      public:
        explicit FrameForwarder(Engine& engine) : engine_(engine) {}
        void on_frame(const Features& features, const ControlFrame& control) noexcept override;
        void on_lane_frame(int lane, const ControlFrame& control) noexcept override;

      private:
        Engine& engine_;
    };

    Settings fitted(const Settings& settings) const;
    // `max_block`: the block size's, or larger (a pipeline primed in larger blocks: the same
    // output for any split, with less of each call's overhead).
    std::unique_ptr<Pipeline> make_pipeline(const Settings& settings, int64_t origin,
                                            int max_block) const;
    void commit(const Settings& next);  // control thread, control_ held
    void apply(const Settings& next);   // control thread, control_ held
    int changes_needed(const Settings& was, const Settings& now) const;
    void swap_in(const Settings& settings);  // control thread, control_ held
    void send(const Change& change);
    void free_retired();  // control thread
    FeatureSet extra_features() const;
    void apply_queued_changes() noexcept;
    void start_crossfade() noexcept;
    void process_chunk(const float* const* in, float* const* out, int offset, int count) noexcept;
    const float* downmix(const float* const* in, int offset, int count) noexcept;
    int first_channel_lane() const noexcept { return summed_loudness_ ? 2 : 1; }
    PipelineInput input_from(const float* const* lanes, int offset,
                             const float** channels) const noexcept;
    static Settings with_first_dc(Settings settings, const std::vector<ActuatorOutput>& outputs);
    std::vector<ActuatorOutput> as_played(const Settings& settings) const;
    void apply_outputs(std::vector<ActuatorOutput> next);  // control_ held
    void retire(Pipeline* pipeline) noexcept;

    Settings settings_;     // control side, control_ held
    uint64_t version_ = 0;  // settings_'s, control_ held
    std::vector<ActuatorOutput> outputs_;
    ProcessSpec spec_;
    int input_channel_ = -1;
    int rate_divisor_ = 1;
    bool prepared_ = false;
    ProgramSource source_ = ProgramSource::analysis;  // control side
    mutable std::mutex control_;  // control threads among themselves, never the audio thread
    std::atomic<int> latency_{0};
    std::atomic<double> hop_samples_{0};

    // Audio side.
    std::unique_ptr<Pipeline> active_;
    Pipeline* incoming_ = nullptr;  // crossfading in
    Change waiting_;                // a pipeline to start once the crossfade is done
    int fade_done_ = 0, fade_samples_ = 1;
    std::vector<OutputTrim> trims_;     // per actuator
    std::vector<float> mono_;           // downmixed input, one chunk
    std::vector<float> mono_catch_up_;  // input a waiting pipeline has not heard, one chunk
    std::vector<std::vector<float>> channels_catch_up_;  // the same of each routed channel
    std::vector<std::vector<float>> incoming_out_;  // the incoming pipeline's output, one chunk
    std::vector<float*> incoming_pointers_;
    // What the analysis read: the mono input (and the summed power), and the input channels a
    // route may take (the first Route::kMaxChannel, when there are several).
    InputRing ring_;
    int routed_channels_ = 0;
    // Several channels analysed as their mean: the loudness is their BS.1770 sum.
    bool summed_loudness_ = false;
    ChannelPower channel_power_;
    std::vector<float> power_, power_catch_up_;  // one chunk
    FrameForwarder forwarder_{*this};
    FrameObserver* observer_ = nullptr;
    std::shared_ptr<const RecordedAnalysis> recording_;  // played back in place of the analysis

    moodycamel::ReaderWriterQueue<Change> changes_{kChangeCapacity};
    moodycamel::ReaderWriterQueue<ControlFrame> injected_{kQueueCapacity};
    moodycamel::ReaderWriterQueue<Pipeline*> retired_{64};
    std::optional<moodycamel::ReaderWriterQueue<AnalysisFrame>> frames_;
    std::optional<moodycamel::ReaderWriterQueue<LaneFrame>> lane_frames_;
};

}  // namespace tactus
