// The analysis stage: causal, block-based feature extraction on a fixed hop grid. Input is
// written in any block size; a frame is analysed each time the input reaches a hop boundary,
// so the features do not depend on the host's block size.
#pragma once

#include <vector>

#include "tactus/analysis/brightness.hpp"
#include "tactus/analysis/dc_blocker.hpp"
#include "tactus/analysis/features.hpp"
#include "tactus/analysis/loudness.hpp"
#include "tactus/analysis/noisiness.hpp"
#include "tactus/analysis/onset_detector.hpp"
#include "tactus/analysis/pitch_yin.hpp"
#include "tactus/analysis/stft_frame.hpp"
#include "tactus/dsp/process_spec.hpp"
#include "tactus/dsp/sample_history.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

class Analyzer {
  public:
    void prepare(const ProcessSpec& spec, const Settings& settings);  // may allocate
    void reset() noexcept;
    // Live (audio thread): the settings that change no buffer (onset thresholds and interval,
    // pitch threshold); the others need prepare().
    void set_live(const Settings& settings) noexcept;

    int hop_samples() const { return hop_samples_; }
    // The hop `settings` give at a sample rate: frames end at multiples of it.
    static int hop_samples_for(const Settings& settings, double sample_rate_hz);
    // The features to compute (all by default); the others keep their Features default.
    void set_features(FeatureSet computed) noexcept { computed_ = computed; }
    // Samples that can be written before the next frame is due (1 ... hop).
    int samples_to_next_frame() const noexcept { return hop_samples_ - filled_; }
    // Takes at most samples_to_next_frame() samples; returns true when a frame is due.
    // Non-finite and denormal samples are read as 0, levels beyond +-kMaxInputLevel are clipped
    // (dsp/sanitize.hpp); a DC offset is removed before the spectral features. `power`, when
    // not null, is the K-weighted power of several channels (engine/channel_power.hpp), which
    // the loudness reads instead of the samples'.
    bool process(const float* samples, const float* power, int count) noexcept;
    bool process(const float* samples, int count) noexcept {
        return process(samples, nullptr, count);
    }
    // The longest a sample waits before a frame reads it.
    int latency() const { return hop_samples_ - 1; }
    // Analyses the frame ending at the newest sample. Call when process() returned true.
    const Features& analyse() noexcept;

  private:
    DcBlocker dc_blocker_;
    SampleHistory history_;
    StftFrame stft_;
    Brightness brightness_;
    Loudness loudness_;
    Noisiness noisiness_;
    PitchYin pitch_;
    OnsetDetector onsets_;
    Features features_;
    std::vector<float> clean_;  // sanitised input, one hop
    int hop_samples_ = 0, filled_ = 0;
    int pitch_every_frames_ = 1, frames_ = 0;
    FeatureSet computed_;
};

}  // namespace tactus
