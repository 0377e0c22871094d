// Attack-decay envelope retriggered by onsets (paper §6: bonk~ drives "a simple envelope
// generator with an adjustable decay"). Attack: linear rise at the slope that goes from 0 to 1 in
// attack_ms, starting from the current level (no jump on retrigger). Decay: exponential towards the
// sustain level, falling 60 dB in decay_ms when sustain is 0. Levels below -140 dB snap to 0, so
// silence stays exact.
#pragma once

#include <cmath>
#include <limits>

#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class Envelope {
  public:
    void prepare(const ProcessSpec& spec) {
        sample_rate_hz_ = spec.sample_rate_hz;
        shaped_attack_ms_ = shaped_decay_ms_ = kUnset;  // none computed at this rate yet
        reset();
    }
    void reset() noexcept {
        level_ = 0.0;
        attacking_ = false;
    }
    void set_shape(double attack_ms, double decay_ms, double sustain) noexcept;
    void trigger() noexcept { attacking_ = true; }
    double level() const { return level_; }
    double next() noexcept;  // inline below: once a sample, a call cost a quarter of it

  private:
    static constexpr double kSilentLevel = 1e-7;
    double sample_rate_hz_ = 48000;
    double attack_step_ = 1.0, decay_coefficient_ = 0.0, sustain_ = 0.0;
    double level_ = 0.0;
    bool attacking_ = false;
    // The times the step and coefficient were computed for: most frames repeat them.
    static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();  // equals none
    double shaped_attack_ms_ = kUnset, shaped_decay_ms_ = kUnset;
};

// The level at this sample, then one step on: sample n after a trigger is the envelope at time
// n / rate, as the oscillator's sample n is its phase at that time, so the product is the same
// signal at any sample rate.
inline double Envelope::next() noexcept {
    const double level = level_;
    if (attacking_) {
        level_ += attack_step_;
        if (level_ >= 1.0) {  // the peak fell between samples: decay for the rest of the step
            const double past_peak = (level_ - 1.0) / attack_step_;  // fraction of a step
            level_ = sustain_ + (1.0 - sustain_) * std::pow(decay_coefficient_, past_peak);
            attacking_ = false;
        }
        return level;
    }
    level_ = sustain_ + (level_ - sustain_) * decay_coefficient_;
    if (sustain_ == 0.0 && level_ < kSilentLevel) level_ = 0.0;
    return level;
}

}  // namespace tactus
