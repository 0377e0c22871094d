// The synthesis stage: oscillator x envelope x amplitude, following the vibration program.
// Each ControlFrame sets targets; amplitude, frequency and mix glide to them per sample with a
// 1 ms one-pole so frame steps do not click. A trigger restarts the envelope, and restarts the
// oscillator phase when the envelope is quiet (so every pulse begins at a zero crossing).
#pragma once

#include "tactus/mapping/control_frame.hpp"
#include "tactus/synthesis/envelope.hpp"
#include "tactus/synthesis/oscillator.hpp"

namespace tactus {

class Voice {
  public:
    void prepare(double sample_rate_hz, double harmonic_limit_hz);
    void reset() noexcept;
    void apply(const ControlFrame& frame) noexcept;
    void render(float* out, int count) noexcept;

  private:
    Oscillator oscillator_;
    Envelope envelope_;
    double glide_ = 0.0;
    double amplitude_ = 0, frequency_hz_ = 0, square_mix_ = 0;
    ControlFrame target_;
};

}  // namespace tactus
