// What a hit's drum part is decided on (analysis/part_model.hpp), read once, settle_ms after its
// onset, from what the hit added above what was sounding (analysis/added_spectrum.hpp), so a
// steady bed of bass, chords or a voice cancels (real-time drum transcription reads band-wise
// rises the same way). Each a number of about unit range, so one linear model reads them all:
//   the added power's log10 share in each of kFineBands log-spaced bands of the 23 ms spectrum
//   (40 Hz to its top, 5.6 kHz at the 16 kHz analysis rate), below 150 Hz and above 6 kHz (the
//   input's bands, analysis/band_power.hpp), and below 150 Hz, at 150 Hz-1 kHz, 1-4 kHz and
//   4 kHz-top of the 10 ms spectrum (the hit's first instants: a kick's click, a snare's crack);
//   the spectral flatness of the added power above 150 Hz (ln of geometric over arithmetic mean:
//   noise 0, a tone far below), which tells a snare's wires from a chord's partials;
//   how far the hit rises above what was sounding (log10 of added over bed power, clipped);
//   how much it has decayed from its strongest reading (dB / 10), a hat's short, a tom's long;
// then the same numbers less their mean over the song's recent hits (exponential, over about
// kRecentHits), so a kit is read against itself: one kit's snare sits below 150 Hz as another's
// kick does, but above its own kick (as real-time drum transcription adapts its templates to the
// kit playing: Dittmar & Gartner 2014, semi-adaptive NMF).
// Audio thread: compute(), reset(); prepare() sets band edges only.
#pragma once

#include <array>
#include <span>

namespace tactus {

// One power spectrum stream: its bins, their width.
struct SpectrumShape {
    int bins = 0;
    double bin_hz = 0;
};

// ln of the geometric over the arithmetic mean of `count` powers (noise 0, a tone far below; an
// empty bin counts as a tiny power).
double log_flatness(const float* powers, int count) noexcept;

class PartFeatures {
  public:
    static constexpr int kFineBands = 7;
    static constexpr int kOwn = kFineBands + 2 + 3 + 3;  // the hit's own numbers
    static constexpr int kCount = 2 * kOwn;              // then relative to the recent hits
    // The recent hits' mean moves 1/kRecentHits of the way to each hit (eval/fit_parts.py: 2 to
    // 8 read alike with two tuning kits left out at a time).
    static constexpr double kRecentHits = 4;

    struct Added {
        std::span<const float> fast, fine, fine_bed;  // power spectra: added, and the bed's
        double low = 0, high = 0;  // the bands' added power, counted as the fast spectrum's bins
        double decay_db = 0;       // strongest level so far less the level now
    };

    void prepare(SpectrumShape fast, SpectrumShape fine);
    void reset() noexcept;  // a new song: no recent hits
    // false: the hit added nothing (the features are left as they were).
    bool compute(const Added& added) noexcept;
    std::span<const float> values() const { return values_; }

  private:
    std::array<int, kFineBands + 1> fine_edges_{};
    std::array<int, 4> fast_edges_{};  // 150 Hz, 1 kHz, 4 kHz, top
    std::array<float, kCount> values_{};
    std::array<float, kOwn> recent_{};  // the recent hits' mean of the own numbers
    bool has_recent_ = false;
};

}  // namespace tactus
