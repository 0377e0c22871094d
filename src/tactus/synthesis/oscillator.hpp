// Band-limited sine <-> square morphing oscillator (paper §3.3, §6: a mix of sine and square
// generators). The square is additive: odd harmonics k up to the harmonic limit, amplitude
// 4/(pi k), the top one faded in/out continuously as f0 moves, so no partial lies above the limit
// and nothing aliases into the vibrotactile band. Harmonics come from the Chebyshev recurrence
// sin((k+4)x) = 2 cos(4x) sin(kx) - sin((k-4)x), two interleaved: one multiply-add per harmonic.
#pragma once

#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class Oscillator {
  public:
    void prepare(const ProcessSpec& spec, double harmonic_limit_hz);
    void reset() noexcept { phase_ = 0.0; }  // restarts the phase: the next sample is sin(0)
    // One sample at frequency_hz, mix 0 (sine) ... 1 (square).
    double next(double frequency_hz, double square_mix) noexcept;

  private:
    double sample_rate_hz_ = 48000, harmonic_limit_hz_ = 1000;
    double phase_ = 0.0;  // cycles, [0, 1)
};

}  // namespace tactus
