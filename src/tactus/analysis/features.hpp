// What the analysis stage reports once per analysis frame (paper Figure 4, left column).
#pragma once

#include <array>
#include <cstdint>

#include "tactus/analysis/drum_part.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

struct Features {
    int64_t frame_end_sample = 0;  // the frame covers input up to (not including) this sample
    double loudness_db = -120;     // K-weighted short-window loudness, dB LKFS scale
    double brightness_hz = 0;      // spectral centroid
    double noisiness = 0;          // Bark-band spectral flatness, 0 tonal ... 1 noise
    double pitch_hz = 0;           // YIN f0, 0 when unvoiced
    double pitch_confidence = 0;   // 0 ... 1
    double onset_odf = 0;          // onset detection function (log spectral flux)
    bool onset = false;            // an onset was decided at frame_end_sample
    int64_t onset_sample = 0;      // its estimated start (valid when onset)
    // What the latest hit added above what was sounding before it (analysis/hit_analysis.hpp).
    double hit_db = -120;             // its loudness now, dB LKFS scale
    double hit_brightness_hz = 0;     // its brightness
    DrumPart part = DrumPart::other;  // the latest hit's part (decided settle_ms after its onset)
    bool part_decided = false;        // ... on this frame
    std::array<float, 3> part_probability{};  // ... and how likely kick, snare, hat each were
    double hit_strength_db = -120;            // the latest hit's strongest level so far

    bool operator==(const Features&) const = default;  // every field (a replayed frame's)
};

// The analysis by cost: loudness (a K filter on every sample), spectrum (brightness, noisiness
// and what each hit adds, with its part: an FFT every hop) and pitch (YIN, as much as the rest
// together). Onsets are always computed: they trigger the envelope. A group nothing reads is
// skipped and keeps its default.
struct FeatureSet {
    bool loudness = true, spectrum = true, pitch = true;

    static constexpr FeatureSet none() { return {false, false, false}; }
    constexpr FeatureSet operator|(FeatureSet other) const {
        return {loudness || other.loudness, spectrum || other.spectrum, pitch || other.pitch};
    }
};

// The group a mapping source reads (onset_odf: none).
constexpr FeatureSet group_of(FeatureSource source) {
    FeatureSet set = FeatureSet::none();
    switch (source) {
        case FeatureSource::loudness_db:
            set.loudness = true;
            break;
        case FeatureSource::brightness_hz:
        case FeatureSource::noisiness:
        case FeatureSource::tonality:
        case FeatureSource::hit_db:
        case FeatureSource::hit_brightness_hz:
            set.spectrum = set.loudness = true;
            break;
        case FeatureSource::pitch_hz:
        case FeatureSource::pitch_confidence:
            set.pitch = true;
            break;
        case FeatureSource::onset_odf:
            break;
    }
    return set;
}

inline double feature_value(const Features& f, FeatureSource source) {
    switch (source) {
        case FeatureSource::loudness_db:
            return f.loudness_db;
        case FeatureSource::brightness_hz:
            return f.brightness_hz;
        case FeatureSource::noisiness:
            return f.noisiness;
        case FeatureSource::tonality:
            return 1.0 - f.noisiness;
        case FeatureSource::pitch_hz:
            return f.pitch_hz;
        case FeatureSource::pitch_confidence:
            return f.pitch_confidence;
        case FeatureSource::onset_odf:
            return f.onset_odf;
        case FeatureSource::hit_db:
            return f.hit_db;
        case FeatureSource::hit_brightness_hz:
            return f.hit_brightness_hz;
    }
    return 0.0;
}

}  // namespace tactus
