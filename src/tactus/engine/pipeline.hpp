// The pipeline of paper Figure 4 for one structural configuration (hop, windows, rates, band,
// routing): mono audio -> analysis -> mapping -> synthesis -> one post chain per distinct
// actuator profile -> actuator outputs. The Engine owns one, and while a structural change is
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
#include "tactus/mapping/mapper.hpp"
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
    // one per actuator (profiles; trims are the engine's). `origin_sample`: the input sample
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
    // Setup: frames played back in place of the analysis, from the next position on (the input
    // is then not analysed: `mono` and `power` are not read); null: analyses the input. The
    // recording must outlive the processing.
    void replay(const RecordedAnalysis* recording) noexcept;
    // Whether input past the recording's end was taken where a frame may have been due.
    bool replay_ran_out() const { return ran_out_; }

    // mono: count <= max_block samples; power: their K-weighted power summed over the input
    // channels (engine/channel_power.hpp), or null (the loudness of `mono`); out: one buffer
    // per actuator. Frames go to `observer` when not null.
    void process(const float* mono, const float* power, float* const* out, int count,
                 FrameObserver* observer) noexcept;

    int rate_divisor() const { return rate_divisor_; }
    FeatureSet analysed_features() const { return analyzer_.features(); }
    double internal_rate_hz() const { return sample_rate_hz_ / rate_divisor_; }
    double hop_samples() const { return analyzer_.hop_samples(); }  // input samples, mean
    int latency() const;
    int64_t position() const { return position_; }  // the next input sample it takes
    const PostChain& post(int actuator) const;
    int64_t clipped_samples() const;

  private:
    void apply_live() noexcept;
    void update_features() noexcept;
    int take_input(const float* mono, const float* power, int count, bool& frame_due) noexcept;
    Features next_features() noexcept;

    double sample_rate_hz_ = 48000;
    int rate_divisor_ = 1;
    int64_t origin_ = 0, position_ = 0;
    LiveSettings live_;
    Analyzer analyzer_;
    Mapper mapper_;
    Voice voice_;
    std::vector<ActuatorChain> chains_;                // one per distinct profile
    std::vector<int> chain_of_;                        // per actuator: its chain
    std::vector<int> first_of_chain_;                  // per chain: the first actuator it feeds
    std::vector<float> carrier_, flutter_, pressure_;  // synthesis, internal rate, one block
    ProgramSource source_ = ProgramSource::analysis;
    FeatureSet extra_features_ = FeatureSet::none();
    const RecordedAnalysis* recording_ = nullptr;
    size_t next_recorded_ = 0;  // the recording's next frame
    bool ran_out_ = false;
    bool post_dirty_ = false;
};

}  // namespace tactus
