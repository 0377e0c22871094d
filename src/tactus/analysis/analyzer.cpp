#include "tactus/analysis/analyzer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tactus/core/units.hpp"
#include "tactus/dsp/sanitize.hpp"

namespace tactus {
namespace {
constexpr double kPitchIntervalMs = 10.0;  // f0 changes slowly: update it every ~10 ms
}

int Analyzer::hop_samples_for(const Settings& settings, double sample_rate_hz) {
    return std::max<int>(
        1, static_cast<int>(ms_to_samples(settings[P::analysis_hop_ms], sample_rate_hz)));
}

void Analyzer::prepare(const ProcessSpec& spec, const Settings& s) {
    const double sample_rate_hz = spec.sample_rate_hz;
    hop_samples_ = hop_samples_for(s, sample_rate_hz);
    stft_.prepare(nearest_power_of_two(ms_to_samples(s[P::analysis_window_ms], sample_rate_hz)),
                  sample_rate_hz);
    brightness_.prepare(stft_.bins(), stft_.bin_hz());
    noisiness_.prepare(stft_.bins(), stft_.bin_hz());
    loudness_.prepare(spec, s[P::loudness_window_ms]);
    pitch_.prepare(spec, {.min_hz = s[P::pitch_min_hz],
                          .max_hz = std::min(s[P::pitch_max_hz], 0.45 * sample_rate_hz),
                          .threshold = s[P::pitch_threshold]});
    onsets_.prepare(spec, hop_samples_,
                    {s[P::onset_window_ms], s[P::onset_threshold], s[P::onset_ratio],
                     s[P::onset_history_ms], s[P::onset_min_interval_ms]});
    history_.prepare(
        std::max({stft_.window_samples(), pitch_.span_samples(), onsets_.span_samples()}));
    clean_.assign(static_cast<size_t>(hop_samples_), 0.0f);
    dc_blocker_.prepare(spec);
    pitch_every_frames_ = std::max(
        1, static_cast<int>(std::lround(kPitchIntervalMs * 1e-3 * sample_rate_hz / hop_samples_)));
    reset();
}

void Analyzer::set_live(const Settings& s) noexcept {
    onsets_.set_thresholds(s[P::onset_threshold], s[P::onset_ratio], s[P::onset_min_interval_ms]);
    pitch_.set_threshold(s[P::pitch_threshold]);
}

void Analyzer::reset() noexcept {
    history_.reset();
    loudness_.reset();
    dc_blocker_.reset();
    onsets_.reset();
    features_ = {};
    filled_ = 0;
    frames_ = 0;
}

bool Analyzer::process(const float* samples, const float* power, int count) noexcept {
    for (int i = 0; i < count; ++i) clean_[i] = sanitized(samples[i]);
    if (computed_.loudness) {
        if (power)
            loudness_.process_power(power, count);
        else
            loudness_.process(clean_.data(), count);
    }
    dc_blocker_.process(clean_.data(), count);
    history_.write(clean_.data(), count);
    filled_ += count;
    return filled_ >= hop_samples_;
}

const Features& Analyzer::analyse() noexcept {
    filled_ = 0;
    Features& f = features_;
    f.frame_end_sample = history_.written();
    if (computed_.loudness) f.loudness_db = loudness_.loudness_db();
    if (computed_.spectrum) {
        stft_.analyse(history_);
        f.brightness_hz = brightness_.centroid_hz(stft_.magnitudes());
        f.noisiness = noisiness_.compute(stft_.powers());
    }
    if (frames_++ % pitch_every_frames_ == 0 && computed_.pitch) {
        const Pitch pitch = pitch_.analyse(history_);
        f.pitch_hz = pitch.f0_hz;
        f.pitch_confidence = pitch.confidence;
    }
    const OnsetDecision onset = onsets_.analyse(history_);
    f.onset_odf = onset.odf;
    f.onset = onset.onset;
    if (onset.onset) f.onset_sample = onset.onset_sample;
    return f;
}

}  // namespace tactus
