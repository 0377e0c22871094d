// NPI flutter component (paper §5.2; Table 1: FAI / Meissner, "flutter", 2-40 Hz): a sine <->
// square oscillator at the flutter rate whose harmonics stop at NPI's upper edge (40 Hz), so the
// flutter stays in its channel and does not buzz the P channel. Rate, level and waveform follow
// the vibration program (ControlFrame::flutter_hz, flutter_amplitude, square_mix); they glide
// with a one-pole whose corner is NPI's upper edge (time constant 1 / (2 pi 40 Hz) = 4 ms), so
// level steps do not click. A rise from silence starts at phase 0; silence is exact zeros.
#pragma once

#include "tactus/dsp/process_spec.hpp"
#include "tactus/mapping/control_frame.hpp"
#include "tactus/synthesis/glide.hpp"
#include "tactus/synthesis/oscillator.hpp"

namespace tactus {

class Flutter {
  public:
    void prepare(const ProcessSpec& spec);
    void reset() noexcept;
    void apply(const ControlFrame& frame) noexcept;
    void process(float* out, int count) noexcept;
    int latency() const { return 0; }

  private:
    Oscillator oscillator_;
    Glide glide_;
    double amplitude_ = 0, rate_hz_ = 0, square_mix_ = 0;
    double target_amplitude_ = 0, target_rate_hz_ = 0, target_square_mix_ = 0;
};

}  // namespace tactus
