#include "tactus/analysis/onset_detector.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/fast_math.hpp"
#include "tactus/core/units.hpp"
#include "tactus/core/vector_clones.hpp"

namespace tactus {
namespace {
constexpr double kLogCompression = 1000.0;  // gamma: magnitudes 60 dB below full scale count
constexpr double kSubBlockMs = 0.5;         // time resolution of the onset-time refinement
// A band below -50 dB counts as silent: a tone fading in from silence leaks a little power
// below 150 Hz whose rise from nothing would read as a hit.
const double kBandFloorAmplitude = std::pow(10.0, -50.0 / 20);

// A band's power read as a sine's amplitude sqrt(2 P), floored, log-compressed as the bins are.
float band_log(double power) noexcept {
    const double amplitude = std::max(std::sqrt(2.0 * power), kBandFloorAmplitude);
    return fast_log(1.0f + static_cast<float>(kLogCompression * amplitude));
}
}  // namespace

void OnsetDetector::prepare(const ProcessSpec& spec, int hop_samples, const OnsetSettings& s) {
    const double sample_rate_hz = spec.sample_rate_hz;
    settings_ = s;
    sample_rate_hz_ = sample_rate_hz;
    hop_samples_ = hop_samples;
    stft_.prepare(nearest_fft_size(ms_to_samples(s.window_ms, sample_rate_hz)), sample_rate_hz);
    bins_ = stft_.bins();
    const auto frames_in = [&](double ms) {
        return std::max(1, static_cast<int>(std::lround(ms * 1e-3 * sample_rate_hz / hop_samples)));
    };
    bins_max_.prepare(bins_, frames_in(kLagMs), frames_in(kSpanMs));
    const double band_lags_ms[2] = {kLowBandLagMs, kLagMs};
    const double band_spans_ms[2] = {kLowBandSpanMs, 2 * kLagMs};
    for (size_t b = 0; b < bands_.size(); ++b) {
        const int lag = frames_in(band_lags_ms[b]);
        bands_[b].prepare(1, lag, std::max(2 * lag, frames_in(band_spans_ms[b])));
    }
    log_magnitudes_.assign(static_cast<size_t>(bins_), 0.0f);
    rise_.assign(static_cast<size_t>(bins_), 0.0f);
    const auto history_frames =
        std::max<int64_t>(1, std::llround(s.history_ms * 1e-3 * sample_rate_hz / hop_samples));
    recent_flux_.prepare(static_cast<int>(history_frames));
    min_interval_samples_ = ms_to_samples(s.min_interval_ms, sample_rate_hz);
    sub_block_samples_ =
        std::max<int>(1, static_cast<int>(ms_to_samples(kSubBlockMs, sample_rate_hz)));
    segment_.assign(static_cast<size_t>(span_samples()), 0.0f);
    block_energy_.assign(static_cast<size_t>(span_samples() / sub_block_samples_), 0.0);
    reset();
}

void OnsetDetector::set_thresholds(const OnsetSettings& s) noexcept {
    settings_.threshold = s.threshold;
    settings_.ratio = s.ratio;
    settings_.min_interval_ms = s.min_interval_ms;
    settings_.low_weight = s.low_weight;
    settings_.high_weight = s.high_weight;
    min_interval_samples_ = ms_to_samples(s.min_interval_ms, sample_rate_hz_);
}

void OnsetDetector::reset() noexcept {
    bins_max_.fill(0.0f);
    for (auto& band : bands_) band.fill(band_log(0.0));  // silence before the stream: the floor
    recent_flux_.fill(0.0);
    last_onset_sample_ = INT64_MIN / 2;
    armed_ = true;
}

TACTUS_VECTOR_CLONES OnsetDecision
OnsetDetector::analyse(const SampleHistory& history, std::array<double, 2> band_power) noexcept {
    stft_.analyse(history);
    const auto& magnitudes = stft_.magnitudes();
    // Each bin's rise over the loudest it was 1 lag to kSpanMs back: a low note's bin swelling as
    // the short window slides along its period must beat its whole period to count.
    for (int k = 0; k < bins_; ++k)
        log_magnitudes_[k] = fast_log(1.0f + static_cast<float>(kLogCompression) * magnitudes[k]);
    bins_max_.rise(log_magnitudes_.data(), rise_.data());
    // Each band as `weight` more bins, its power read as a sine's amplitude sqrt(2 P).
    const double weights[2] = {settings_.low_weight, settings_.high_weight};
    double bands_rise = 0;
    for (size_t b = 0; b < bands_.size(); ++b)
        bands_rise += weights[b] * bands_[b].rise(band_log(band_power[b]));
    const double flux = (sum_of(rise_.data(), bins_) + bands_rise) * 100.0 / bins_;  // per 100 bins

    // Median of the recent flux: the background level, not raised by the hits themselves.
    const double threshold = settings_.threshold + settings_.ratio * recent_flux_.median();
    recent_flux_.push(flux);

    OnsetDecision decision{flux, false, 0};
    const int64_t now = history.written();
    if (flux <= threshold) {
        armed_ = true;
    } else if (armed_ && now - last_onset_sample_ >= min_interval_samples_) {
        armed_ = false;
        last_onset_sample_ = now;
        decision.onset = true;
        decision.onset_sample = refine_onset_sample(history);
    }
    return decision;
}

// The sub-block with the largest energy rise over its predecessor, within the newest window and
// hop: where the new sound begins.
TACTUS_VECTOR_CLONES int64_t
OnsetDetector::refine_onset_sample(const SampleHistory& history) noexcept {
    const int span = span_samples();
    history.read_latest(segment_.data(), span);
    const int blocks = static_cast<int>(block_energy_.size());
    const int offset = span - blocks * sub_block_samples_;
    double loudest = 0.0;
    for (int b = 0; b < blocks; ++b) {
        const auto first = static_cast<size_t>(offset) +
                           static_cast<size_t>(b) * static_cast<size_t>(sub_block_samples_);
        const double e = sum_of_squares(segment_.data() + first, sub_block_samples_);
        block_energy_[b] = e;
        loudest = std::max(loudest, e);
    }
    const double floor = 1e-4 * loudest + 1e-20;
    double best_ratio = 0.0;
    int best_block = blocks - 1;
    for (int b = 1; b < blocks; ++b) {
        const double ratio = (block_energy_[b] + floor) / (block_energy_[b - 1] + floor);
        if (ratio > best_ratio) best_ratio = ratio, best_block = b;
    }
    const int64_t start = history.written() - span + offset;
    return std::max<int64_t>(0, start + static_cast<int64_t>(best_block) * sub_block_samples_);
}

}  // namespace tactus
