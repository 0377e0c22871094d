// The pipeline of paper Figure 4 for one structural configuration (hop, windows, rates, band,
// routes): audio -> analysis -> mapping -> synthesis -> post chains -> actuator outputs. Each
// distinct input a route hears (engine/route.hpp: the engine's mix, a band of it, an input
// channel) has one analysis; each distinct way of playing one (a route's parts, an output's
// overlay: the values its mapping, synthesis and post chains take in place of the settings')
// one lane: its mapping and synthesis, and one post chain per distinct actuator profile among
// its outputs. With every output on `all`, as by default, that is one of each: the
// paper's one signal for every tonehole. The Engine owns one, and while a structural change is
// swapped in, two (engine.hpp). Live settings reach it through ask(); everything in it after
// prepare() runs on the audio thread (or, before it is handed over, on the control thread that
// primes it) and never allocates.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "tactus/analysis/analyzer.hpp"
#include "tactus/dsp/upsampler.hpp"
#include "tactus/engine/actuator_chain.hpp"
#include "tactus/engine/live_settings.hpp"
#include "tactus/engine/output_trim.hpp"
#include "tactus/engine/recorded_analysis.hpp"
#include "tactus/engine/route.hpp"
#include "tactus/mapping/mapper.hpp"
#include "tactus/post/band_limit.hpp"
#include "tactus/synthesis/voice.hpp"

namespace tactus {

// Where the synthesis takes its vibration program from.
enum class ProgramSource { analysis, external, both };

// Receives every analysis frame and the control frame mapped from it, on the audio thread,
// inside process(): an implementation must itself be real-time safe when used live.
class FrameObserver {
  public:
    virtual ~FrameObserver() = default;
    virtual void on_frame(const Features& features, const ControlFrame& control) noexcept = 0;
    // The features on_frame() reads besides the onsets (all by default); the engine computes
    // only these and what the mapping reads.
    virtual FeatureSet reads() const noexcept { return {}; }
    // The vibration program each lane plays (its route's: a part route only its parts' pulses),
    // after on_frame() of the same frame; Pipeline::lane_of() tells an actuator's lane.
    virtual void on_lane_frame(int /*lane*/, const ControlFrame& /*control*/) noexcept {}
};

// One block of input, as the pipeline reads it.
struct PipelineInput {
    const float* mono = nullptr;   // the engine's mix: the mean of the channels or the chosen one
    const float* power = nullptr;  // its K-weighted power summed over the channels, or null
    // The input channels (at most Route::kMaxChannel): what channel routes hear; null when
    // no route takes one.
    const float* const* channels = nullptr;
};

class Pipeline {
  public:
    static constexpr double kMinInternalRateHz = 11025;
    // Output samples per internal sample (synthesis and the actuator chains) at a rate.
    static int rate_divisor_for(double sample_rate_hz) {
        return std::clamp(static_cast<int>(sample_rate_hz / kMinInternalRateHz), 1,
                          Upsampler::kMaxFactor);
    }

    // Allocates. spec.max_block: mono samples one process() call takes at most. `outputs`:
    // one per actuator (profiles and routes; trims are the engine's); spec.channels: the input
    // channels a channel route may take. `origin_sample`: the input sample
    // its first sample is (frame positions).
    void prepare(const ProcessSpec& spec, const Settings& settings,
                 const std::vector<ActuatorOutput>& outputs, int64_t origin_sample = 0);
    void reset() noexcept;  // also to origin 0

    void ask(P id, double value) noexcept { live_.ask(id, value); }
    void glide_flattening(const FlatteningFilter::Design& design) noexcept;
    void set_source(ProgramSource source) noexcept { source_ = source; }
    void apply(ControlFrame frame) noexcept;  // an injected frame, from now
    // The features the analysis computes beyond the mapping's (the engine's readers').
    void set_extra_features(FeatureSet features) noexcept;
    // Setup: frames played back in place of the mix's analysis, from the next position on (the
    // mix is then not analysed: `power` is not read, `mono` only by band routes); null: analyses
    // the input. The recording must outlive the processing.
    void replay(const RecordedAnalysis* recording) noexcept;
    // Whether input past the recording's end was taken where a frame may have been due.
    bool replay_ran_out() const { return ran_out_; }

    // in: count <= max_block samples of each; out: one buffer per actuator. The mix's frames,
    // mapped with the running settings, go to `observer` when not null.
    void process(const PipelineInput& in, float* const* out, int count,
                 FrameObserver* observer) noexcept;

    int rate_divisor() const { return rate_divisor_; }
    int lanes() const { return static_cast<int>(lanes_.size()); }
    int lane_of(int actuator) const { return lane_of_[static_cast<size_t>(actuator)]; }
    FeatureSet analysed_features() const { return listenings_.front().analyzer.features(); }
    double internal_rate_hz() const { return sample_rate_hz_ / rate_divisor_; }
    double hop_samples() const {  // input samples, mean
        return listenings_.front().analyzer.hop_samples();
    }
    int latency() const;
    int64_t position() const { return position_; }  // the next input sample it takes
    const PostChain& post(int actuator) const;
    int64_t clipped_samples() const;

  private:
    // One analysis (route.hpp): of the mix (the first: the observer's frames, and what a
    // recording replaces), or of a band of it or an input channel.
    struct Listening {
        Route route;               // all, band or channel
        BandLimit band;            // band: the input's band
        std::vector<float> heard;  // band: one block filtered
        Analyzer analyzer;
        bool frame_due = false;
    };
    // One way of playing a listening's frames: with an output's overlay and, for a part route,
    // only its parts' pulses; its synthesis; post chains first_chain ... + chains.
    struct Lane {
        int listening = 0;
        Route route;
        Overlay overlay;
        bool program = false;  // all, no overlay: plays the observer's frames as they are
        Mapper mapper;
        Voice voice;
        std::vector<float> carrier, flutter, pressure;  // internal rate, one block
        size_t first_chain = 0, chains = 0;
        bool own_pulse = false;  // parts: the sounding pulse is one of its parts'
    };

    void apply_live() noexcept;
    void refer_pressures() noexcept;
    void update_features() noexcept;
    int take_input(const PipelineInput& in, int offset, int count) noexcept;
    const float* heard(const Listening& listening, const PipelineInput& in, int offset) const;
    Features next_features(Listening& listening) noexcept;
    void play(int lane, const Features& features, const ControlFrame& program,
              FrameObserver* observer) noexcept;
    double lane_ceiling(const Lane& lane) const {
        return chains_[lane.first_chain].post().ceiling();
    }

    double sample_rate_hz_ = 48000;
    int rate_divisor_ = 1;
    int64_t origin_ = 0, position_ = 0;
    LiveSettings live_;
    std::vector<Listening> listenings_;
    std::vector<Lane> lanes_;
    Mapper program_;                     // the mix's frames, the running settings: the observer's
    std::vector<ActuatorChain> chains_;  // lane by lane, one per distinct profile
    std::vector<int> chain_of_;          // per actuator: its chain
    std::vector<int> lane_of_;           // per actuator: its lane
    std::vector<int> first_of_chain_;    // per chain: the first actuator it feeds
    ProgramSource source_ = ProgramSource::analysis;
    FeatureSet extra_features_ = FeatureSet::none();
    const RecordedAnalysis* recording_ = nullptr;
    size_t next_recorded_ = 0;  // the recording's next frame
    bool ran_out_ = false;
    bool post_dirty_ = false;
};

}  // namespace tactus
