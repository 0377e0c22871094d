#include "tactus/actuator/compensation.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {
double ActuatorCompensation::target_db(double frequency_hz) const {
    const double f = std::clamp(frequency_hz, actuator_.band_low_hz, actuator_.band_high_hz);
    // Outside the band nothing is lifted towards what the actuator cannot play: the edge's
    // value falls away at the profile's roll-off.
    const double outside_octaves =
        std::abs(std::log2(std::max(frequency_hz, FitBand::kLowestHz) / f));
    return std::clamp(-actuator_.response_db(f), -kBoundDb, kBoundDb) -
           actuator_.rolloff_db_per_octave * outside_octaves;
}

double ActuatorCompensation::notch_db(double frequency_hz) const {
    return notch_on_ ? notch_.coefficients().magnitude_db(frequency_hz, sample_rate_hz_) +
                           gain_to_db(notch_gain_)
                     : 0.0;
}

double ActuatorCompensation::magnitude_db(double frequency_hz) const {
    return notch_db(frequency_hz) + eq_.magnitude_db(frequency_hz);
}

void ActuatorCompensation::prepare(const ProcessSpec& spec, const ActuatorProfile& actuator) {
    const double sample_rate_hz = spec.sample_rate_hz;
    actuator_ = actuator;
    sample_rate_hz_ = sample_rate_hz;
    notch_on_ = actuator.resonance == ResonanceKind::band_pass &&
                actuator.resonance_hz < 0.45 * sample_rate_hz;
    if (notch_on_) {
        const double q = actuator.q * std::pow(10.0, -kBoundDb / 40.0);
        notch_.set(
            BiquadCoefficients::peaking(actuator.resonance_hz, q, -kBoundDb, sample_rate_hz));
        notch_gain_ = db_to_gain(kBoundDb - actuator.response_db(actuator.resonance_hz));
    }
    eq_.prepare(spec,
                FittedEq::fit(sample_rate_hz,
                              FitBand::octave_beyond(actuator.band_low_hz, actuator.band_high_hz),
                              [this](double f) { return target_db(f) - notch_db(f); }));
    reset();
}

void ActuatorCompensation::process(float* samples, int count) noexcept {
    if (notch_on_)
        for (int i = 0; i < count; ++i)
            samples[i] = static_cast<float>(notch_gain_ * notch_.process(samples[i]));
    eq_.process(samples, count);
}

}  // namespace tactus
