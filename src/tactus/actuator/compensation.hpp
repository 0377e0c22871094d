// Output compensation for an actuator profile: the inverse of its displacement response inside
// its usable band (relative to reference_hz), so that equal signal levels give equal skin
// displacement there, bounded to +-kBoundDb; realised by FittedEq over the usable band. The
// same idea as Android's HapticGenerator notch at the LRA's resonance (perception.md), derived
// from the profile instead of fixed.
#pragma once

#include "tactus/actuator/profile.hpp"
#include "tactus/post/fitted_eq.hpp"

namespace tactus {

class ActuatorCompensation {
  public:
    static constexpr double kBoundDb = 12.0;

    void prepare(double sample_rate_hz, const ActuatorProfile& actuator);  // may allocate
    void reset() noexcept { eq_.reset(); }
    void process(float* samples, int count) noexcept { eq_.process(samples, count); }

    double target_db(double frequency_hz) const;
    double magnitude_db(double frequency_hz) const { return eq_.magnitude_db(frequency_hz); }

  private:
    ActuatorProfile actuator_;
    FittedEq eq_;
};

}  // namespace tactus
