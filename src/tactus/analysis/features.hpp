// What the analysis stage reports once per analysis frame (paper Figure 4, left column).
#pragma once

#include <cstdint>

#include "tactus/core/params.hpp"

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
};

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
    }
    return 0.0;
}

}  // namespace tactus
