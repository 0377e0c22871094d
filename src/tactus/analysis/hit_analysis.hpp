// What a hit adds to the sound: the drum parts inside music (paper §6: brightness "used for drum
// part separation", read here on the hit instead of on the whole mix). At each onset the power
// spectrum of the last frame that ended before the hit began is kept as what was already sounding
// (bass, chords, voice, the previous hit's tail). Every frame from then to the next onset, the
// hit's spectrum is the newest power spectrum less that one, bin by bin, where positive. From it:
//   level_db       the power the hit added, dB re full scale (a full-scale 1 kHz sine added reads
//                  -3.01, as BS.1770 reads it), so a soft hit over a loud chord reads soft;
//   brightness_hz  its log-frequency centroid up to brightness.max_hz (analysis/brightness.hpp);
//   part           kick, snare, hat or other, decided once, settle_ms after the onset, from where
//                  the added power lies: a kick's below 150 Hz, a hat's above 3 kHz with little
//                  below 1 kHz, a snare's spread across both, the rest (a bass note, a chord, a
//                  voice) with little above 3 kHz and little below 150 Hz ... see classify().
// Audio thread: analyse() every frame; prepare() allocates.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tactus/analysis/brightness.hpp"
#include "tactus/analysis/drum_part.hpp"

namespace tactus {

struct HitSettings {
    double brightness_max_hz = 1500;
    double settle_ms = 8;  // onset -> its part decided
};

class HitAnalysis {
  public:
    // `bins` and `bin_hz`: the spectra analyse() is given; `longest_wait_samples`: the most
    // analysis samples an onset's start can lie before the frame that decides it.
    void prepare(int bins, double bin_hz, double sample_rate_hz, int hop_samples,
                 int longest_wait_samples, const HitSettings& settings);
    void reset() noexcept;
    void set_live(const HitSettings& settings) noexcept;  // audio thread

    // One frame ending at analysis sample `now`: its power spectrum, and the start of an onset
    // this frame decided (`onset_start` < 0: none).
    void analyse(std::span<const float> powers, int64_t now, int64_t onset_start) noexcept;

    double level_db() const { return level_db_; }
    double brightness_hz() const { return brightness_hz_; }
    // The latest hit's strongest level so far (its strength), and its part.
    double peak_db() const { return peak_db_; }
    DrumPart part() const { return part_; }
    // The latest hit's part was decided this frame.
    bool part_decided() const { return part_decided_; }

  private:
    DrumPart classify() const noexcept;
    const float* past(int frames_back) const noexcept;

    Brightness brightness_;
    std::vector<float> ring_;       // the last frames_ power spectra, bins_ each
    std::vector<float> reference_;  // what was sounding when the latest hit began
    std::vector<float> added_, added_magnitude_;
    int bins_ = 0, frames_ = 0, position_ = 0, hop_samples_ = 1;
    int low_bins_ = 0, mid_bins_ = 0, high_bin_ = 0;  // band edges in bins (classify())
    double sample_rate_hz_ = 16000;
    int64_t settle_samples_ = 0, hit_start_ = -1;
    double level_db_ = -120, brightness_hz_ = 0, peak_db_ = -120;
    DrumPart part_ = DrumPart::other;
    bool part_decided_ = false, deciding_ = false;
};

}  // namespace tactus
