// The synthesis stage, one component per channel of touch (paper §5): the P carrier (§5.1:
// oscillator x envelope x amplitude, the paper's §6 synthesiser), the NPI flutter (§5.2) and the
// NPIII pressure (§5.4), all following the vibration program. Each ControlFrame sets targets;
// the carrier's amplitude, frequency and mix glide to them per sample with a 1 ms one-pole so
// frame steps do not click. A trigger restarts the envelope, and restarts the oscillator phase
// when the envelope is quiet (so every pulse begins at a zero crossing). The components render
// into separate buffers because the post chain routes them differently (post_chain.hpp).
#pragma once

#include "tactus/dsp/process_spec.hpp"
#include "tactus/mapping/control_frame.hpp"
#include "tactus/synthesis/envelope.hpp"
#include "tactus/synthesis/flutter.hpp"
#include "tactus/synthesis/glide.hpp"
#include "tactus/synthesis/oscillator.hpp"
#include "tactus/synthesis/pressure.hpp"

namespace tactus {

class Voice {
  public:
    void prepare(const ProcessSpec& spec, double harmonic_limit_hz);
    void reset() noexcept;
    void apply(const ControlFrame& frame) noexcept;
    // The P carrier alone.
    void process(float* out, int count) noexcept;
    // Carrier, flutter and pressure; a null buffer skips its component (it is off).
    void process(float* carrier, float* flutter, float* pressure, int count) noexcept;
    int latency() const { return 0; }

  private:
    Oscillator oscillator_;
    Envelope envelope_;
    Flutter flutter_;
    Pressure pressure_;
    Glide glide_;
    double amplitude_ = 0, frequency_hz_ = 0, square_mix_ = 0;
    ControlFrame target_;
};

}  // namespace tactus
