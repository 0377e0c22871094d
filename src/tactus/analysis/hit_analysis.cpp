#include "tactus/analysis/hit_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/analysis/band_power.hpp"
#include "tactus/analysis/loudness.hpp"
#include "tactus/analysis/model_terms.hpp"
#include "tactus/analysis/part_model.hpp"
#include "tactus/core/fast_math.hpp"
#include "tactus/core/vector_clones.hpp"

namespace tactus {
namespace {
// A Hann-windowed sine of amplitude 1 centred on a bin reads power 1 there and 1/4 in each
// neighbour (stft_frame.hpp): 1.5 in all, for a mean power of 1/2. The high band is a mean
// power: times 3 it counts as the spectrum's bins do.
constexpr double kBinsPerMeanPower = 2 * 1.5;
constexpr double kSilentDb = Loudness::kFloorDb;
// Inputs below 32 kHz, which have no high band for the part model, keep a rule on where a drum's
// added power lies (Sonic Pi and General MIDI kits; eval/results.md): a kick's
// body in the low band (below BandPower::kLowEdgeHz), a snare's shell from there to kMidEdgeHz
// and its wires above, a hat's in the high band.
constexpr double kMidEdgeHz = 1000;
// Without the high band (inputs below 32 kHz), the analysis's own top stands in for it.
constexpr double kTopEdgeHz = 4000;
// The shares that tell them apart, fitted on the tuning part of the music corpus
// (eval/music_corpus.py).
constexpr double kHatAboveShare = 0.15, kHatLowShare = 0.2;
constexpr double kKickLowPerMid = 1.0, kKickLowShare = 0.2;

// The part model (analysis/part_model.hpp): the hit's own numbers and their pairwise products,
// then its numbers relative to the recent hits, standardised; the class of the largest linear
// score, and each class's probability (the scores' softmax: a multinomial logistic regression).
TACTUS_VECTOR_CLONES DrumPart modelled_part(std::span<const float> x,
                                            std::array<float, 3>& probability) noexcept {
    using namespace part_model;
    constexpr size_t kOwn = PartFeatures::kOwn;
    std::array<float, kTerms> z{};
    std::ranges::copy(x.subspan(kOwn), put_quadratic(x.first(kOwn), z.data()));
    standardise(z, kMean.data(), kScale.data());
    int best = 0;
    double best_score = 0;
    std::array<double, kClasses> scores{};
    for (int c = 0; c < kClasses; ++c) {
        const auto k = static_cast<size_t>(c);
        const double score = linear_score(z, kWeights[k].data(), kBias[k]);
        scores[k] = score;
        if (c == 0 || score > best_score) best = c, best_score = score;
    }
    double sum = 0;
    for (double& score : scores) sum += (score = std::exp(score - best_score));
    for (size_t k = 0; k < scores.size(); ++k) probability[k] = static_cast<float>(scores[k] / sum);
    return static_cast<DrumPart>(best);
}

}  // namespace

void HitAnalysis::prepare(SpectrumShape fast, SpectrumShape fine, double sample_rate_hz,
                          int hop_samples, int longest_wait_samples, bool high_band,
                          const HitSettings& settings) {
    sample_rate_hz_ = sample_rate_hz;
    has_high_band_ = high_band;
    for (AddedSpectrum* one : {&loudness_, &low_, &high_})
        one->prepare(1, hop_samples, longest_wait_samples, sample_rate_hz);
    fast_.prepare(fast.bins, hop_samples, longest_wait_samples, sample_rate_hz);
    fine_.prepare(fine.bins, hop_samples, longest_wait_samples, sample_rate_hz);
    fine_magnitude_.assign(static_cast<size_t>(fine.bins), 0.0f);
    const auto bin_of = [&](double hz) {
        return std::clamp(static_cast<int>(std::ceil(hz / fast.bin_hz)), 1, fast.bins);
    };
    low_bins_ = bin_of(BandPower::kLowEdgeHz);
    mid_bins_ = bin_of(kMidEdgeHz);
    top_bins_ = bin_of(kTopEdgeHz);
    features_.prepare(fast, fine);
    rises_.prepare(fast, fine);
    high_recent_.prepare(hop_samples, sample_rate_hz, longest_wait_samples);
    brightness_.prepare(fine.bins, fine.bin_hz, settings.brightness_max_hz);
    set_live(settings);
    reset();
}

void HitAnalysis::set_live(const HitSettings& settings) noexcept {
    brightness_.set_max_hz(settings.brightness_max_hz);
    settle_samples_ = std::llround(settings.settle_ms * 1e-3 * sample_rate_hz_);
    drum_min_ = settings.drum_min;
}

void HitAnalysis::reset() noexcept {
    for (AddedSpectrum* each : {&loudness_, &low_, &high_, &fast_, &fine_}) each->reset();
    high_recent_.reset();
    features_.reset();
    hit_start_ = -1;
    level_db_ = peak_db_ = kSilentDb;
    brightness_hz_ = 0;
    part_ = DrumPart::other;
    probability_ = {};
    part_decided_ = deciding_ = features_read_ = rises_read_ = false;
}

void HitAnalysis::analyse(const Frame& frame, int64_t now, int64_t onset_start) noexcept {
    const auto one = [&](AddedSpectrum& added, double value) {
        const auto bin = static_cast<float>(value);
        added.analyse({&bin, 1}, now, onset_start);
    };
    one(loudness_, frame.loudness_mean_square);
    one(low_, frame.low_band_power);
    one(high_, frame.high_band_power);
    fast_.analyse(frame.fast, now, onset_start);
    fine_.analyse(frame.fine, now, onset_start);
    high_recent_.push(frame.high_band_newest);
    if (onset_start >= 0) {
        hit_start_ = onset_start;
        peak_db_ = kSilentDb;
        deciding_ = true;
        features_read_ = false;
    }
    // The loudness's rise, or where the mix's loudness fell under a hit (a hat on a snare's decay)
    // what the fast spectrum and the high band added bin by bin, as a mean square (bin by bin a
    // noise's own fluctuations add too, about 3 dB over a bed: only where the loudness says
    // nothing).
    const double rise = loudness_.added_sum();
    level_db_ = Loudness::db_of(
        rise > 0 ? rise : fast_.added_sum() / kBinsPerMeanPower + high_.added_sum());
    peak_db_ = std::max(peak_db_, level_db_);
    const auto& added = fine_.added();
    for (size_t k = 0; k < added.size(); ++k) fine_magnitude_[k] = std::sqrt(added[k]);
    brightness_hz_ = brightness_.centroid_hz(fine_magnitude_);
    part_decided_ = false;
    // Not a drum's onset by how its bands rose (onset_rises.hpp): `other` at once, before its
    // pulse starts. Without the high band the model cannot be read: every onset waits for its
    // part. With drum_min off nothing reads it, and its numbers (about 4 k instructions on an
    // onset's frame, which set a 64-frame block's p99) are not computed.
    if (onset_start >= 0) rises_read_ = has_high_band_ && (drum_min_ > 0 || rises_always_);
    if (onset_start >= 0 && rises_read_) {
        const auto band = [](const AddedSpectrum& one) {
            return OnsetRises::Band{.before = one.reference()[0], .added = one.added()[0]};
        };
        rises_.compute({.fast_before = fast_.reference(),
                        .fast_added = fast_.added(),
                        .fine_added = fine_.added(),
                        .low = band(low_),
                        .high = band(high_),
                        .loudness = band(loudness_),
                        .high_over_recent = high_recent_.rise(now, onset_start)});
        if (drum_min_ > 0 && rises_.drum_probability() < drum_min_) {
            part_ = DrumPart::other;
            probability_ = {};
            part_decided_ = true;
            deciding_ = false;
        }
    }
    if (deciding_ && now - hit_start_ >= settle_samples_) {
        const bool added = features_.compute({.fast = fast_.added(),
                                              .fine = fine_.added(),
                                              .fine_bed = fine_.reference(),
                                              .low = kBinsPerMeanPower * low_.added_sum(),
                                              .high = kBinsPerMeanPower * high_.added_sum(),
                                              .decay_db = peak_db_ - level_db_});
        features_read_ = added;
        part_ = !added           ? DrumPart::other
                : has_high_band_ ? modelled_part(features_.values(), probability_)
                                 : rule_part();
        if (!added || !has_high_band_) {
            probability_ = {};
            if (part_ != DrumPart::other) probability_[static_cast<size_t>(part_)] = 1;
        }
        part_decided_ = true;
        deciding_ = false;
    }
}

// Without the high band: the shares of the added power (the fast spectrum's 10 ms window and the
// low band's, weighted alike) below 150 Hz, at 150 Hz-1 kHz and from 4 kHz up (the fast
// spectrum's top, standing in for the high band) decide: a hat adds 15 % or more at the top and
// little below 150 Hz; a kick adds at least as much below 150 Hz as at 150 Hz-1 kHz; the rest is
// a snare.
DrumPart HitAnalysis::rule_part() const noexcept {
    const auto& added = fast_.added();
    const int bins = static_cast<int>(added.size());
    const double low = kBinsPerMeanPower * low_.added_sum();
    const double mid = sum_of(added.data() + low_bins_, mid_bins_ - low_bins_);
    const double upper = sum_of(added.data() + mid_bins_, top_bins_ - mid_bins_);
    const double above = sum_of(added.data() + top_bins_, bins - top_bins_);
    const double total = low + mid + upper + above;
    if (total <= 0) return DrumPart::other;
    if (above > kHatAboveShare * total && low < kHatLowShare * total) return DrumPart::hat;
    if (low >= kKickLowPerMid * mid && low > kKickLowShare * total) return DrumPart::kick;
    return DrumPart::snare;
}

}  // namespace tactus
