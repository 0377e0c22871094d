// Output compensation for an actuator profile: the inverse of its displacement response inside
// its usable band (relative to reference_hz), so that equal signal levels give equal skin
// displacement there, bounded to +-kBoundDb. A band-pass resonance (an LRA) is inverted by a
// peaking cut of kBoundDb at f0 with Q' = Q 10^(-kBoundDb/40), followed by the gain that brings
// f0 to its target (kBoundDb less the response at f0): exactly |s^2 + s/Q + 1| /
// |s^2 + s/Q'' + 1| scaled, Q'' = Q 10^(-kBoundDb/20), the inverse resonance levelling off at the
// bound away from f0 (Android's HapticGenerator notches its LRA's f0 likewise:
// docs/perception.md). What remains (tables, low-pass resonances) is fitted by FittedEq over the
// usable band.
#pragma once

#include "tactus/actuator/profile.hpp"
#include "tactus/dsp/biquad.hpp"
#include "tactus/dsp/fitted_eq.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class ActuatorCompensation {
  public:
    static constexpr double kBoundDb = 12.0;

    void prepare(const ProcessSpec& spec, const ActuatorProfile& actuator);  // may allocate
    int latency() const { return 0; }                                        // minimum phase
    void reset() noexcept {
        notch_.reset();
        eq_.reset();
    }
    void process(float* samples, int count) noexcept;

    double target_db(double frequency_hz) const;
    double magnitude_db(double frequency_hz) const;

  private:
    double notch_db(double frequency_hz) const;  // the resonance's inverse, with its gain
    ActuatorProfile actuator_;
    double sample_rate_hz_ = 48000;
    bool notch_on_ = false;
    Biquad notch_;
    double notch_gain_ = 1.0;
    FittedEq eq_;
};

}  // namespace tactus
