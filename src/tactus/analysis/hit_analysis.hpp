// What each hit adds to the sound, and which drum part it is: the drum parts inside music
// (paper §6: brightness "used for drum part separation", read here on what the hit added instead
// of on the whole mix, so bass, chords and a voice neither brighten a kick nor darken a snare).
// What was sounding is subtracted (analysis/added_spectrum.hpp) from these readings:
//   the K-weighted loudness's power (10 ms, a rectangular window: as fast as the loudness);
//   the onset detector's 10 ms spectrum and the input's power below 150 Hz and above 6 kHz
//   (analysis/band_power.hpp, Hann-weighted as that spectrum is), for the part;
//   the 23 ms analysis spectrum, for the brightness (its bins resolve a kick's body).
// Read from them, every frame until the next onset:
//   level_db       the loudness the hit added, dB LKFS scale (or, where the mix's loudness
//                  fell under it, the power it added bin by bin), so a soft hit over a loud
//                  chord reads soft;
//   brightness_hz  its log-frequency centroid up to brightness.max_hz (analysis/brightness.hpp);
// and its part: `other` at once, on the onset's own frame, when the onset model gives it less
// than drum_min of being a drum's (analysis/onset_rises.hpp); else, settle_ms after the onset,
// kick, snare or hat by the part model (analysis/part_model.hpp, fitted by eval/fit_parts.py) on
// where and how the added power lies (analysis/part_features.hpp), `other` when the hit added
// nothing.
// Audio thread: analyse(); prepare() allocates.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "tactus/analysis/added_spectrum.hpp"
#include "tactus/analysis/brightness.hpp"
#include "tactus/analysis/drum_part.hpp"
#include "tactus/analysis/onset_rises.hpp"
#include "tactus/analysis/part_features.hpp"
#include "tactus/analysis/recent_loudest.hpp"

namespace tactus {

struct HitSettings {
    double brightness_max_hz = 1500;
    double settle_ms = 20;  // onset -> its part decided
    double drum_min = 0;    // an onset less likely a drum's is `other` at once (0: off)
};

class HitAnalysis {
  public:
    // `longest_wait_samples`: the most analysis samples an onset's start can lie before the
    // frame that decides it.
    // `high_band`: the input has the 6-10 kHz band (analysis/band_power.hpp); without it the
    // part model cannot be read, and a rule on the fast spectrum's band shares decides.
    void prepare(SpectrumShape fast, SpectrumShape fine, double sample_rate_hz, int hop_samples,
                 int longest_wait_samples, bool high_band, const HitSettings& settings);
    void reset() noexcept;
    void set_live(const HitSettings& settings) noexcept;  // audio thread

    // The readings of one frame.
    struct Frame {
        double loudness_mean_square = 0;
        std::span<const float> fast, fine;  // power spectra
        double low_band_power = 0, high_band_power = 0;
        double high_band_newest = 0;  // the high band's plain power over the newest frame
    };
    // One frame ending at analysis sample `now`, and the start of an onset this frame decided
    // (< 0: none).
    void analyse(const Frame& frame, int64_t now, int64_t onset_start) noexcept;

    double level_db() const { return level_db_; }
    double brightness_hz() const { return brightness_hz_; }
    // The latest hit's strongest level so far (its strength), and its part.
    double peak_db() const { return peak_db_; }
    DrumPart part() const { return part_; }
    // Each of kick, snare and hat's probability by the part model when it decided part() (one
    // for the part a rule decided; none for `other`).
    const std::array<float, 3>& part_probability() const { return probability_; }
    // The latest hit's part was decided this frame.
    bool part_decided() const { return part_decided_; }
    // What the latest hit's part was read from (analysis/part_features.hpp), when the part model
    // read it (an onset that was not a drum's, or that added nothing, has none).
    bool part_features_read() const { return features_read_; }
    std::span<const float> part_features() const { return features_.values(); }
    // The onset model reads every onset of an input with the high band, not only while drum_min
    // is on (tactus onsets --part-features); else its numbers are not computed.
    void read_every_onset(bool every) noexcept { rises_always_ = every; }
    // What the latest onset was told a drum's or not by (analysis/onset_rises.hpp), when read.
    bool onset_rises_read() const { return rises_read_; }
    std::span<const float> onset_rises() const { return rises_.values(); }

  private:
    DrumPart rule_part() const noexcept;

    AddedSpectrum fast_, fine_;
    AddedSpectrum loudness_, low_, high_;  // each a spectrum of one bin
    Brightness brightness_;
    PartFeatures features_;
    OnsetRises rises_;
    RecentLoudest high_recent_;
    std::vector<float> fine_magnitude_;
    int low_bins_ = 0, mid_bins_ = 0, top_bins_ = 0;  // band edges in fast bins (rule_part())
    bool has_high_band_ = true, rises_always_ = false, rises_read_ = false;
    double sample_rate_hz_ = 16000, drum_min_ = 0;
    int64_t settle_samples_ = 0, hit_start_ = -1;
    double level_db_ = -120, brightness_hz_ = 0, peak_db_ = -120;
    DrumPart part_ = DrumPart::other;
    std::array<float, 3> probability_{};
    bool part_decided_ = false, deciding_ = false, features_read_ = false;
};

}  // namespace tactus
