// NPIII pressure component (paper §5.4; Table 1: SAI / Merkel, "pressure", 0.4-3 Hz): a slow,
// non-negative offset that presses the actuator into the skin, following
// ControlFrame::pressure (a continuous level or steps, from the mapping stage). Changes glide
// with a one-pole whose corner is NPIII's upper edge (time constant 1 / (2 pi 3 Hz) = 53 ms), so
// a step is felt as pressure rather than as a tap. Only for actuators that hold a sustained
// offset (actuator.dc); the mapping stage sends 0 otherwise. Silence is exact zeros.
#pragma once

#include "tactus/dsp/process_spec.hpp"
#include "tactus/mapping/control_frame.hpp"
#include "tactus/synthesis/glide.hpp"

namespace tactus {

class Pressure {
  public:
    void prepare(const ProcessSpec& spec);
    void reset() noexcept { level_ = target_ = 0.0; }
    void apply(const ControlFrame& frame) noexcept { target_ = frame.pressure; }
    void process(float* out, int count) noexcept;
    int latency() const { return 0; }

  private:
    Glide glide_;
    double level_ = 0.0, target_ = 0.0;
};

}  // namespace tactus
