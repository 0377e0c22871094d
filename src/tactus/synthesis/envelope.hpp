// Attack-decay envelope retriggered by onsets (paper §6: bonk~ drives "a simple envelope
// generator with an adjustable decay"). Attack: linear rise at the slope that goes from 0 to 1 in
// attack_ms, starting from the current level (no jump on retrigger). Decay: exponential towards the
// sustain level, falling 60 dB in decay_ms when sustain is 0. Levels below -140 dB snap to 0, so
// silence stays exact.
#pragma once

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
    double next() noexcept;

  private:
    double sample_rate_hz_ = 48000;
    double attack_step_ = 1.0, decay_coefficient_ = 0.0, sustain_ = 0.0;
    double level_ = 0.0;
    bool attacking_ = false;
    // The times the step and coefficient were computed for: most frames repeat them.
    static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();  // equals none
    double shaped_attack_ms_ = kUnset, shaped_decay_ms_ = kUnset;
};

}  // namespace tactus
