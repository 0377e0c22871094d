// The longest stretch of sound a render turned into no vibration, for the warning (render and
// export) that a preset of discrete pulses leaves a sustained sound (an explosion's rumble, a
// drone, a held chord) unfelt after its onset's pulse. Sound: an analysis frame's loudness above
// the mapping's gate and within kSoundBelowLoudestDb of the loudest so far (a reverb tail or a
// fade-out is no stretch to warn about). No vibration: every output sample under kUnfelt (-40
// dBFS). Fed by one render's worker, in the order the engine delivers: each frame's loudness (its
// observer, inside process(), or its frame queue before the block), then each output block; no
// allocation.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "tactus/params/params.hpp"

namespace tactus::cli {

class UnfeltSound {
  public:
    // A passage more than 30 dB under the loudest (a tail dying away) is not what is missed.
    static constexpr double kSoundBelowLoudestDb = 30;
    // -40 dBFS: 10 dB under the quietest pulse the presets map (amplitude out_min 0.03).
    static constexpr float kUnfelt = 0.01f;
    static constexpr double kLongStretchS = 1.0;  // what a warning is worth

    // The render's settings: the mapping's gate, and whether its envelope sustains (a sustaining
    // preset follows a sound past its onset: only "no vibration at all" is warned of).
    explicit UnfeltSound(const Settings& settings)
        : gate_db_(settings[P::mapping_gate_db]), sustains_(settings[P::envelope_sustain] != 0) {}

    void on_loudness(double loudness_db) noexcept {
        loudest_db_ = std::max(loudest_db_, loudness_db);
        sounding_ = loudness_db > gate_db_ && loudness_db > loudest_db_ - kSoundBelowLoudestDb;
    }
    // One output block: v[channel][0 ... frames).
    void on_output(const float* const* v, int channels, int frames) noexcept {
        float peak = 0.0f;
        for (int c = 0; c < channels; ++c)
            for (int i = 0; i < frames; ++i) peak = std::max(peak, std::abs(v[c][i]));
        peak_ = std::max(peak_, peak);
        if (sounding_ && peak < kUnfelt) {
            if (run_frames_ == 0) run_start_ = written_;
            run_frames_ += frames;
            if (run_frames_ > longest_frames_) {
                longest_frames_ = run_frames_;
                longest_start_ = run_start_;
            }
        } else {
            run_frames_ = 0;
        }
        written_ += frames;
    }

    float peak() const { return peak_; }  // the output's, all blocks

    // The one-line warning for `input` once its run is over, or "" when the vibration followed
    // the sound: audible input and no vibration at all, or (a preset without sustain) a long
    // stretch of sound after an onset's pulse. Names the preset that follows loudness.
    std::string warning(const std::string& input, double sample_rate_hz) const;

  private:
    double gate_db_, loudest_db_ = -std::numeric_limits<double>::infinity();
    bool sustains_, sounding_ = false;
    float peak_ = 0;
    int64_t written_ = 0, run_start_ = 0, run_frames_ = 0;
    int64_t longest_frames_ = 0, longest_start_ = 0;
};

}  // namespace tactus::cli
