// The energy of the input above the analysis band, for the onset detection function: a closed
// hi-hat keeps 84 % of its first 50 ms above 5.6 kHz (Sonic Pi's drum_cymbal_closed), where the
// 16 kHz analysis (analyzer.hpp) cannot see it, and where bass, chords and most of a voice have
// little energy, so hats stay audible to the detector inside a mix (band-wise onset functions,
// as in real-time drum transcription). A 4th-order Butterworth high-pass at kEdgeHz, squared,
// read at each analysis frame as the mean power over the last window_frames frames: as it is
// (for the onset detection function, which decides sooner on it) and weighted by a Hann window
// as the onset detector's spectrum is (stft_frame.hpp), so that the two read a hit's shares alike. Inputs whose band ends
// below kEdgeHz + kMinWidthHz have no high band: power() stays 0.
// Audio thread: process(), frame(); prepare() allocates.
#pragma once

#include <array>
#include <vector>

#include "tactus/dsp/biquad.hpp"

namespace tactus {

class HighBand {
  public:
    static constexpr double kEdgeHz = 6000;
    static constexpr double kMinWidthHz = 2000;

    void prepare(double sample_rate_hz, int window_frames);
    void reset() noexcept;
    bool active() const { return active_; }
    void process(const float* samples, int count) noexcept;
    struct Power {
        double mean = 0, hann = 0;  // mean power over the window, plain and Hann-weighted
    };
    // Closes one analysis frame: the power over the newest window of frames.
    Power frame() noexcept;

  private:
    std::array<Biquad, 2> sections_;
    std::vector<double> energy_;  // energy of each of the last frames, a ring
    std::vector<int> samples_;    // and their sample counts
    std::vector<double> weight_;  // Hann weight of each frame back
    int position_ = 0;
    bool active_ = false;
};

}  // namespace tactus
