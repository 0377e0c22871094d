// Whether an onset is a drum's, read on the frame that decides it, before its pulse starts, so
// that a drums-only mapping (parts.drum_min with parts.other.gain_db = -60, presets/drums.toml)
// never starts the pulse of a bass note, a chord or a syllable it can tell apart. The numbers:
// how far each band rose over what was sounding (analysis/added_spectrum.hpp: log10 of the
// band's power now over its power just before the onset), below 150 Hz and at 6-10 kHz (the
// input's bands, analysis/band_power.hpp), at 150-400 Hz, 400 Hz-1 kHz, 1-2.5 kHz and 2.5 kHz
// to the top of the 10 ms spectrum, and of the K-weighted loudness; and the flatness of what it
// added above 150 Hz in the 10 ms and the 23 ms spectra (ln of geometric over arithmetic mean:
// noise 0, a tone far below); and how far the 6-10 kHz band rose over its loudest of the 50 ms
// before the onset (analysis/recent_loudest.hpp). A drum rises at once across the spectrum, most
// above 6 kHz, as noise, and over what the mix's highs just did; a pitched note in a few bands,
// as partials. A logistic model over them and their pairwise products (analysis/part_model.hpp,
// fitted by eval/fit_parts.py) gives the probability that the onset is a drum's.
// Audio thread: compute(), drum_probability(); prepare() sets band edges only.
#pragma once

#include <array>
#include <span>

#include "tactus/analysis/part_features.hpp"

namespace tactus {

class OnsetRises {
  public:
    static constexpr int kCount = 10;

    // One band's power just before the onset and what the onset added to it.
    struct Band {
        double before = 0, added = 0;
    };
    struct Frame {
        std::span<const float> fast_before, fast_added;  // the 10 ms spectrum's powers
        std::span<const float> fine_added;               // the 23 ms spectrum's added power
        Band low, high, loudness;
        float high_over_recent = 0;  // analysis/recent_loudest.hpp
    };

    void prepare(SpectrumShape fast, SpectrumShape fine);
    void compute(const Frame& frame) noexcept;
    std::span<const float> values() const { return values_; }
    // The model's reading of the latest values, 0 to 1.
    double drum_probability() const noexcept;

  private:
    std::array<int, 5> fast_edges_{};  // 150 Hz, 400 Hz, 1 kHz, 2.5 kHz, top
    int fine_first_ = 1;               // 150 Hz
    std::array<float, kCount> values_{};
};

}  // namespace tactus
