// The power of the input in a band at either end of the spectrum, for the onset detection
// function and the drum parts (band-wise onset functions, as real-time drum transcription uses):
//   high: 6-10 kHz, above the 16 kHz analysis (analyzer.hpp), which a closed hi-hat's energy
//         reaches (84 % of its first 50 ms lies above 5.6 kHz, Sonic Pi's drum_cymbal_closed)
//         and where bass, chords and most of a voice have little, so hats stay audible in a mix;
//   low:  below 150 Hz, a kick's body: a sub kick lights one or two of the analysis spectrum's
//         bins, which a busy bed's flux outweighs.
// 4th-order Butterworth filters at the input rate (the high band's top edge keeps it about the
// same band at every rate from 22.05 kHz up), squared, read at each analysis frame as the mean
// power over the last window_frames frames: as it is (for the onset detection function, which
// decides sooner on it) and weighted by a Hann window as the onset detector's spectrum is
// (stft_frame.hpp), so that the two read a hit's shares alike. An input rate whose
// Nyquist frequency is below kHighTopHz * kTopMargin has no high band: its power stays 0 (a
// 16 kHz input).
// Audio thread: process(), open(), close(), frame(); prepare() allocates.
#pragma once

#include <array>
#include <vector>

#include "tactus/dsp/biquad.hpp"

namespace tactus {

class BandPower {
  public:
    enum class Band { low, high };
    static constexpr double kLowEdgeHz = 150;
    static constexpr double kHighEdgeHz = 6000, kHighTopHz = 10000, kTopMargin = 1.05;
    static constexpr int kLowSections = 2, kHighSections = 4;  // the filters' biquads

    void prepare(Band band, double sample_rate_hz, int window_frames);
    bool active() const { return active_; }  // false: a high band the input rate cannot hold
    void reset() noexcept;
    void process(const float* samples, int count) noexcept;

    // process() for a caller that runs a copy of the band's filters (filters()) in one wavefront
    // with other filters (Analyzer's CascadeLanes): open() the newest frame's energy, take() the
    // square of each filtered sample in order, close() it with the samples' count.
    struct Energy {
        double sum = 0;
        void take(double square) noexcept { sum += square; }
    };
    Energy open() const noexcept { return {energy_[static_cast<size_t>(position_)]}; }
    void close(Energy energy, int count) noexcept;
    // The band's filters, kLowSections or kHighSections biquads in turn.
    const Biquad* filters() const noexcept { return sections_.data(); }

    struct Power {
        double mean = 0, hann = 0;  // mean power over the window, plain and Hann-weighted
        double newest = 0;          // mean power over the newest frame alone
    };
    // Closes one analysis frame: the power over the newest window of frames.
    Power frame() noexcept;

  private:
    std::array<Biquad, kHighSections> sections_;
    int section_count_ = kLowSections;
    std::vector<double> energy_;  // energy of each of the last frames, a ring
    std::vector<int> samples_;    // and their sample counts
    std::vector<double> weight_;  // Hann weight of each frame back
    int position_ = 0;
    bool active_ = false;
};

}  // namespace tactus
