// Causal onset detection (the role of bonk~ in the paper, §6).
// Detection function: log-compressed spectral flux of a short-window STFT, i.e. the mean over
// bins of the half-wave rectified rise of log(1 + gamma |X|) over the loudest of the frames
// kLagMs to kSpanMs before (Klapuri 1999; Böck & Widmer 2013 for the log compression and the
// temporal maximum). The lags are in time, not frames: a shorter hop samples the same function
// more often, so it decides sooner with the same thresholds. Peak picking is causal: an onset is
// decided the first frame the flux exceeds an adaptive threshold, threshold + ratio * median of the
// recent flux, at least min_interval after the previous onset; it re-arms when the flux falls back
// below the threshold. The onset time is then refined in the time domain to the sub-millisecond
// block with the largest energy rise in the newest window.
// The input's power below 150 Hz and above 6 kHz (analysis/band_power.hpp) each add their own
// rise, of their log-compressed power over the same lags, weighted as low_weight and high_weight
// bins of the spectrum: a sub kick that lights one bin, the hats a 16 kHz analysis cannot see.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "tactus/analysis/sliding_median.hpp"
#include "tactus/analysis/stft_frame.hpp"
#include "tactus/analysis/temporal_max.hpp"
#include "tactus/dsp/process_spec.hpp"
#include "tactus/dsp/sample_history.hpp"

namespace tactus {

struct OnsetSettings {
    double window_ms = 5.8;
    double threshold = 10;
    double ratio = 1.25;
    double history_ms = 60;
    double min_interval_ms = 50;
    double low_weight = 5;
    double high_weight = 30;
};

struct OnsetDecision {
    double odf = 0;  // detection function value this frame
    bool onset = false;
    int64_t onset_sample = 0;  // estimated start of the onset (valid when onset)
};

class OnsetDetector {
  public:
    // Two default hops (1.45 ms), where the thresholds were tuned.
    static constexpr double kLagMs = 2.9;
    // A period of a 67 Hz bass note: the 10 ms window sees a part of a low note's period, so its
    // bins swell and fade each period and a reference only 2 lags back reads each swell as a
    // rise (onsets in music at a 0 dB bed, eval/results.md: precision 0.79-0.86 with the frames
    // 2.9 and 5.8 ms back, 0.88-0.92 with these).
    static constexpr double kSpanMs = 15;
    // The low band's: a kick's body takes a quarter period or so to rise (16 ms at 60 Hz).
    static constexpr double kLowBandLagMs = 8.7;
    // Its rise is over the loudest of its frames back to a 29 Hz period: the band's power swells
    // and fades with its lowest notes' periods and with a rumble's slow beats, not hits.
    static constexpr double kLowBandSpanMs = 35;

    void prepare(const ProcessSpec& spec, int hop_samples, const OnsetSettings& settings);
    void reset() noexcept;
    // Live (audio thread): threshold, ratio and minimum interval; the windows stay as prepared.
    void set_thresholds(const OnsetSettings& settings) noexcept;
    // Analyses the frame ending at the newest sample of `history`, with the bands' mean power
    // over the same window ({low, high}; 0 without one).
    OnsetDecision analyse(const SampleHistory& history, std::array<double, 2> band_power) noexcept;
    int span_samples() const { return stft_.window_samples() + hop_samples_; }
    // The power spectrum of the frame analyse() last read.
    const StftFrame& frame() const { return stft_; }

  private:
    int64_t refine_onset_sample(const SampleHistory& history) noexcept;

    OnsetSettings settings_;
    double sample_rate_hz_ = 48000;
    StftFrame stft_;
    std::vector<float> log_magnitudes_, rise_, segment_;  // the first two: per bin, this frame
    TemporalMax bins_max_;              // the bins' log magnitudes, kLagMs to kSpanMs back
    std::array<TemporalMax, 2> bands_;  // low, high: their log power over their own lags
    SlidingMedian recent_flux_;         // over onset.history_ms
    std::vector<double> block_energy_;  // per sub-block of segment_
    int hop_samples_ = 0, sub_block_samples_ = 0, bins_ = 0;
    int64_t min_interval_samples_ = 0, last_onset_sample_ = INT64_MIN / 2;
    bool armed_ = true;
};

}  // namespace tactus
