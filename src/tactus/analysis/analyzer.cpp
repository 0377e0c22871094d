#include "tactus/analysis/analyzer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "tactus/core/units.hpp"
#include "tactus/core/vector_clones.hpp"
#include "tactus/dsp/real_fft.hpp"
#include "tactus/dsp/sanitize.hpp"

namespace tactus {
namespace {
constexpr double kPitchIntervalMs = 10.0;  // f0 changes slowly: update it every ~10 ms

// The resampler's ratio for an input rate: to kAnalysisRateHz, or 1:1 below it.
Resampler::Ratio analysis_ratio(double sample_rate_hz) {
    return Resampler::ratio_for(sample_rate_hz,
                                std::min(Analyzer::kAnalysisRateHz, sample_rate_hz));
}

// Where the input filters' outputs go (Analyzer::filter_input): the loudness's K-weighted
// squares (when kLoudness) and the bands' energies, carried by value in the wavefront's sink
// (cascades_each returns it), so they stay in registers.
template <bool kLoudness>
struct InputSums {
    Loudness::Squares loudness;
    BandPower::Energy low, high;
    void operator()(int chain, int, double y) noexcept {
        const double square = y * y;
        if (chain == 0) {
            if (kLoudness) loudness.take(square);
        } else if (chain == 1) {
            low.take(square);
        } else {
            high.take(square);
        }
    }
};
}  // namespace

double Analyzer::analysis_rate_for(double sample_rate_hz) {
    const auto ratio = analysis_ratio(sample_rate_hz);
    return sample_rate_hz * static_cast<double>(ratio.up) / static_cast<double>(ratio.down);
}

int Analyzer::hop_for(const Settings& settings, double analysis_rate_hz) {
    return std::max<int>(
        1, static_cast<int>(ms_to_samples(settings[P::analysis_hop_ms], analysis_rate_hz)));
}

double Analyzer::hop_samples_for(const Settings& settings, double sample_rate_hz) {
    const double analysis_rate = analysis_rate_for(sample_rate_hz);
    return sample_rate_hz * hop_for(settings, analysis_rate) / analysis_rate;
}

// Frame k ends after input floor((k H - 1) M / L) + 1: the same ends, shifted, from any start
// that is a multiple of M H / gcd(H, L) input samples.
int64_t Analyzer::frame_grid_samples(const Settings& settings, double sample_rate_hz) {
    const auto ratio = analysis_ratio(sample_rate_hz);
    const int64_t hop = hop_for(settings, analysis_rate_for(sample_rate_hz));
    return ratio.down * (hop / std::gcd(hop, ratio.up));
}

void Analyzer::prepare(const ProcessSpec& spec, const Settings& s) {
    sample_rate_hz_ = spec.sample_rate_hz;
    const double analysis_rate = analysis_rate_for(sample_rate_hz_);
    hop_ = hop_for(s, analysis_rate);
    const auto ratio = analysis_ratio(sample_rate_hz_);
    const auto max_inputs = static_cast<int>(hop_ * ratio.down / ratio.up + 2);
    resampler_.prepare(sample_rate_hz_, std::min(kAnalysisRateHz, sample_rate_hz_), max_inputs);
    const ProcessSpec analysis{.sample_rate_hz = analysis_rate, .max_block = max_inputs};
    RealFft::PlanTogether ffts;  // the frames' and the pitch's, planned at once below
    stft_.prepare(nearest_fft_size(ms_to_samples(s[P::analysis_window_ms], analysis_rate)),
                  analysis_rate);
    brightness_.prepare(stft_.bins(), stft_.bin_hz(), s[P::brightness_max_hz]);
    noisiness_.prepare(stft_.bins(), stft_.bin_hz());
    loudness_.prepare(spec, s[P::loudness_window_ms]);
    pitch_.prepare(analysis, {.min_hz = s[P::pitch_min_hz],
                              .max_hz = std::min(s[P::pitch_max_hz], 0.45 * analysis_rate),
                              .threshold = s[P::pitch_threshold]});
    onsets_.prepare(analysis, hop_, onset_settings(s));
    ffts.plan();
    const int band_window_frames = std::max(
        1, static_cast<int>(std::lround(ms_to_samples(s[P::onset_window_ms], analysis_rate) /
                                        static_cast<double>(hop_))));
    low_band_.prepare(BandPower::Band::low, sample_rate_hz_, band_window_frames);
    high_band_.prepare(BandPower::Band::high, sample_rate_hz_, band_window_frames);
    input_filters_.load({loudness_.filters(), low_band_.filters(), high_band_.filters()});
    hits_.prepare({onsets_.frame().bins(), onsets_.frame().bin_hz()},
                  {stft_.bins(), stft_.bin_hz()}, analysis_rate, hop_, onsets_.span_samples(),
                  high_band_.active(), hit_settings(s));
    history_.prepare(
        std::max({stft_.window_samples(), pitch_.span_samples(), onsets_.span_samples()}));
    clean_.assign(static_cast<size_t>(max_inputs), 0.0f);
    analysed_.assign(static_cast<size_t>(max_inputs), 0.0f);
    dc_blocker_.prepare(analysis);
    pitch_every_frames_ =
        std::max(1, static_cast<int>(std::lround(kPitchIntervalMs * 1e-3 * analysis_rate / hop_)));
    reset();
}

OnsetSettings Analyzer::onset_settings(const Settings& s) {
    return {.window_ms = s[P::onset_window_ms],
            .threshold = s[P::onset_threshold],
            .ratio = s[P::onset_ratio],
            .history_ms = s[P::onset_history_ms],
            .min_interval_ms = s[P::onset_min_interval_ms],
            .low_weight = s[P::onset_low_weight],
            .high_weight = s[P::onset_high_weight]};
}

HitSettings Analyzer::hit_settings(const Settings& s) {
    return {.brightness_max_hz = s[P::brightness_max_hz],
            .settle_ms = s[P::parts_settle_ms],
            .drum_min = s[P::parts_drum_min]};
}

bool Analyzer::reads(P id) {
    static constexpr P kRead[] = {
        P::analysis_window_ms, P::analysis_hop_ms,   P::loudness_window_ms,    P::pitch_min_hz,
        P::pitch_max_hz,       P::pitch_threshold,   P::onset_window_ms,       P::onset_threshold,
        P::onset_ratio,        P::onset_history_ms,  P::onset_min_interval_ms, P::onset_low_weight,
        P::onset_high_weight,  P::brightness_max_hz, P::parts_settle_ms,       P::parts_drum_min};
    return std::find(std::begin(kRead), std::end(kRead), id) != std::end(kRead);
}

void Analyzer::set_live(const Settings& s) noexcept {
    hits_.set_live(hit_settings(s));
    onsets_.set_thresholds(onset_settings(s));
    pitch_.set_threshold(s[P::pitch_threshold]);
    brightness_.set_max_hz(s[P::brightness_max_hz]);
}

void Analyzer::reset() noexcept {
    resampler_.reset();
    history_.reset();
    loudness_.reset();
    dc_blocker_.reset();
    onsets_.reset();
    low_band_.reset();
    high_band_.reset();
    input_filters_.reset();
    hits_.reset();
    features_ = {};
    inputs_ = 0;
    next_frame_end_ = hop_;
    frames_ = 0;
}

TACTUS_VECTOR_CLONES bool Analyzer::process(const float* samples, const float* power,
                                            int count) noexcept {
    for (int i = 0; i < count; ++i) clean_[i] = sanitized(samples[i]);
    // The loudness reads several channels' power when given, else K-weights the samples.
    if (computed_.loudness && power) loudness_.process_power(power, count);
    if (computed_.loudness && !power)
        filter_input<true>(count);
    else
        filter_input<false>(count);
    inputs_ += count;
    const int analysed = resampler_.process(clean_.data(), count, analysed_.data());
    dc_blocker_.process(analysed_.data(), analysed);
    history_.write(analysed_.data(), analysed);
    return history_.written() >= next_frame_end_;
}

// loudness_.process(clean_) (when k_weigh), low_band_.process(clean_) and
// high_band_.process(clean_), their filters in one wavefront (input_filters_): bit for bit the
// same, the filters advancing together instead of one after the other. The high band's lanes
// run even where the band is inactive (a 16 kHz input), as pass-throughs nobody reads.
template <bool k_weigh>
void Analyzer::filter_input(int count) noexcept {
    InputSums<k_weigh> sums{loudness_.open(), low_band_.open(), high_band_.open()};
    sums = input_filters_.each(
        count, [&](int, int i) { return static_cast<double>(clean_[i]); }, sums);
    if (k_weigh) loudness_.close(sums.loudness);
    low_band_.close(sums.low, count);
    if (high_band_.active()) high_band_.close(sums.high, count);
}

const Features& Analyzer::analyse() noexcept {
    next_frame_end_ += hop_;
    Features& f = features_;
    f.frame_end_sample = inputs_;
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
    const BandPower::Power low_band = low_band_.frame(), high_band = high_band_.frame();
    const OnsetDecision onset = onsets_.analyse(history_, {low_band.mean, high_band.mean});
    f.onset_odf = onset.odf;
    f.onset = onset.onset;
    if (computed_.spectrum) {
        hits_.analyse({.loudness_mean_square = loudness_.mean_square(),
                       .fast = onsets_.frame().powers(),
                       .fine = stft_.powers(),
                       .low_band_power = low_band.hann,
                       .high_band_power = high_band.hann,
                       .high_band_newest = high_band.newest},
                      history_.written(), onset.onset ? onset.onset_sample : -1);
        f.hit_db = hits_.level_db();
        f.hit_brightness_hz = hits_.brightness_hz();
        f.part = hits_.part();
        f.part_decided = hits_.part_decided();
        f.part_probability = hits_.part_probability();
        f.hit_strength_db = hits_.peak_db();
    }
    if (onset.onset) {  // analysis sample -> input sample, less the resampler's delay
        const double inputs_per_analysed =
            static_cast<double>(resampler_.down()) / static_cast<double>(resampler_.up());
        const double at =
            (static_cast<double>(onset.onset_sample) - resampler_.delay_output_samples()) *
            inputs_per_analysed;
        f.onset_sample = std::max<int64_t>(0, std::llround(at));
    }
    return f;
}

}  // namespace tactus
