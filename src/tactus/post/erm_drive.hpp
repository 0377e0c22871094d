// An ERM's drive from the vibration: its intensity, shaped for a motor whose speed follows the
// drive with a lag (docs/perception.md "Actuators": 50-100 ms rise; its vibration frequency is
// tied to the speed, so the carrier's frequency cannot reach the skin, only its intensity).
// The intensity is the carrier's envelope (|x| through a 2-pole low-pass at kEnvelopeHz, times
// pi/2: a sine's peak). The motor's speed is the one-pole lag actuator/actuator_model.hpp
// simulates (time constant from the profile's rise_ms); the drive inverts it sample by sample,
// bounded to +-ceiling: full drive while the motor spins up to the envelope, reverse drive
// (braking, as ERM drivers such as TI's DRV2605 do) while it must slow down, the envelope's own
// level once it is there. Unipolar in use (the braking is brief): the post chain's last
// band-limit, which would remove it, is left out for an ERM (post_chain.hpp).
// prepare() on a control thread; reset() and process() on the audio thread, real-time safe.
#pragma once

#include "tactus/dsp/biquad.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class ErmDrive {
  public:
    // Above the motor's lag (2.2 / (2 pi 75 ms) ~ 5 Hz at the shipped profile's rise), below
    // twice the lowest carrier a fitted ERM mapping plays (2 x 120 Hz): the ripple of |x| is
    // 2f and is cut by (240 / 15)^2, 48 dB.
    static constexpr double kEnvelopeHz = 15.0;

    void prepare(const ProcessSpec& spec, double spin_time_constant_ms);  // may allocate
    void reset() noexcept;
    // In place: the limited carrier in, the drive out, within +-ceiling.
    void process(float* samples, int count, double ceiling) noexcept;
    int latency() const { return 0; }

  private:
    Biquad envelope_;
    double follow_ = 1.0;  // the motor's one-pole coefficient per sample
    double speed_ = 0.0;   // the motor's speed, in drive units (what a steady drive reaches)
};

}  // namespace tactus
