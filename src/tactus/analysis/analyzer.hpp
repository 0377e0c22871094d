// The analysis stage: causal, block-based feature extraction on a fixed hop grid. Input is
// written in any block size; a frame is analysed each time the input reaches a hop boundary,
// so the features do not depend on the host's block size.
//
// Rates. The spectral features, the pitch and the onsets are computed at one analysis rate,
// kAnalysisRateHz, whatever the input rate (16-192 kHz; an input below it is analysed at its
// own rate): a Resampler brings the input there, so every window and hop is the same number of
// analysis samples, the spectrum ends at the same frequency and the same music gives the same
// frames at any input rate. Content above the resampler's pass band (5.6 kHz; 60 dB down from
// 7.2 kHz) is ignored, which also keeps broadband noise out of the onset detection. Loudness
// (BS.1770 K-weighting, defined at any rate) is computed on the input itself. Frame ends and onset
// times are input samples: analysis sample n stands at input position n * M / L
// (dsp/resampler.hpp), exactly.
#pragma once

#include <cmath>
#include <vector>

#include "tactus/analysis/band_power.hpp"
#include "tactus/analysis/brightness.hpp"
#include "tactus/analysis/features.hpp"
#include "tactus/analysis/hit_analysis.hpp"
#include "tactus/analysis/loudness.hpp"
#include "tactus/analysis/noisiness.hpp"
#include "tactus/analysis/onset_detector.hpp"
#include "tactus/analysis/pitch_yin.hpp"
#include "tactus/analysis/stft_frame.hpp"
#include "tactus/dsp/biquad_cascade.hpp"
#include "tactus/dsp/dc_blocker.hpp"
#include "tactus/dsp/process_spec.hpp"
#include "tactus/dsp/resampler.hpp"
#include "tactus/dsp/sample_history.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

class Analyzer {
  public:
    static constexpr double kAnalysisRateHz = 16000;

    void prepare(const ProcessSpec& spec, const Settings& settings);  // may allocate
    void reset() noexcept;
    // Live (audio thread): the settings that change no buffer (onset thresholds, weights and
    // interval, pitch threshold, brightness.max_hz, parts.settle_ms); the others need prepare().
    void set_live(const Settings& settings) noexcept;

    // The rate the features are computed at: kAnalysisRateHz (or the input rate below it),
    // within 0.05 % for an input rate with no exact ratio (Resampler::kMaxPhases).
    double analysis_rate_hz() const { return resampler_.output_rate_hz(); }
    static double analysis_rate_for(double sample_rate_hz);
    // Analysis samples per frame.
    int hop_analysis_samples() const { return hop_; }
    double frame_rate_hz() const { return analysis_rate_hz() / hop_; }
    // Input samples per frame, on average (frames end at whole input samples), as prepared or
    // as `settings` give at a sample rate.
    double hop_samples() const { return sample_rate_hz_ / frame_rate_hz(); }
    static double hop_samples_for(const Settings& settings, double sample_rate_hz);
    // The input samples after which frame ends repeat: a pipeline started at a multiple of it
    // has the frame grid of one started at 0 (engine.hpp: structural changes).
    static int64_t frame_grid_samples(const Settings& settings, double sample_rate_hz);
    // The features to compute (all by default); the others keep their Features default.
    void set_features(FeatureSet computed) noexcept { computed_ = computed; }
    FeatureSet features() const noexcept { return computed_; }
    // Input samples that can be written before the next frame is due (>= 1).
    int samples_to_next_frame() const noexcept {
        return static_cast<int>(resampler_.inputs_for(next_frame_end_ - 1) - inputs_);
    }
    // Takes at most samples_to_next_frame() samples; returns true when a frame is due.
    // Non-finite and denormal samples are read as 0, levels beyond +-kMaxInputLevel are clipped
    // (dsp/sanitize.hpp); a DC offset is removed before the spectral features. `power`, when
    // not null, is the K-weighted power of several channels (engine/channel_power.hpp), which
    // the loudness reads instead of the samples'.
    bool process(const float* samples, const float* power, int count) noexcept;
    bool process(const float* samples, int count) noexcept {
        return process(samples, nullptr, count);
    }
    // The longest an input sample waits before a frame reads it.
    int latency() const { return static_cast<int>(std::ceil(hop_samples())); }
    // Analyses the frame ending at the newest sample. Call when process() returned true.
    const Features& analyse() noexcept;
    // What each hit added and its part (read after analyse()).
    const HitAnalysis& hits() const { return hits_; }
    // The onset model reads every onset (HitAnalysis::read_every_onset).
    void read_every_onset(bool every) noexcept { hits_.read_every_onset(every); }
    // The onset detector's settings among `settings`.
    static OnsetSettings onset_settings(const Settings& settings);
    // Whether the analysis reads parameter `id` (prepare() or set_live()): the features of an
    // input change with these only, so a recorded analysis (engine/recorded_analysis.hpp) stays
    // valid while the others change.
    static bool reads(P id);

  private:
    static int hop_for(const Settings& settings, double analysis_rate_hz);
    static HitSettings hit_settings(const Settings& settings);
    template <bool k_weigh>
    void filter_input(int count) noexcept;

    Resampler resampler_;
    DcBlocker dc_blocker_;
    SampleHistory history_;  // analysis rate
    StftFrame stft_;
    Brightness brightness_;
    Loudness loudness_;  // input rate
    Noisiness noisiness_;
    PitchYin pitch_;
    OnsetDetector onsets_;
    HitAnalysis hits_;
    BandPower low_band_, high_band_;  // input rate
    // The filters of loudness_, low_band_ and high_band_, in that order, run side by side.
    CascadeLanes<KWeighting::kSections, BandPower::kLowSections, BandPower::kHighSections>
        input_filters_;
    Features features_;
    std::vector<float> clean_;     // sanitised input, one hop
    std::vector<float> analysed_;  // clean_ at the analysis rate
    double sample_rate_hz_ = 48000;
    int hop_ = 0;
    int64_t inputs_ = 0, next_frame_end_ = 0;  // input samples taken; analysis sample
    int pitch_every_frames_ = 1, frames_ = 0;
    FeatureSet computed_;
};

}  // namespace tactus
