#include "tactus/actuator/actuator_model.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {
const double kRiseTimeConstants = std::log(9.0);  // a one-pole's 10-90 % rise, in time constants
constexpr double kDbPerOctavePerSection = 12.0;   // a 2nd-order Butterworth edge's asymptote
constexpr double kStillSpeed = 1e-12;             // below it the motor stands: silence stays silent
}  // namespace

double erm_spin_time_constant_ms(const ActuatorProfile& actuator) {
    return actuator.rise_ms / kRiseTimeConstants;
}

double ActuatorModel::fixed_db(double f) const {
    double db = resonance_on_ ? resonance_.coefficients().magnitude_db(f, sample_rate_hz_) : 0.0;
    for (int k = 0; k < edge_count_; ++k)
        db += edges_[static_cast<size_t>(k)].coefficients().magnitude_db(f, sample_rate_hz_);
    return db;
}

double ActuatorModel::magnitude_db(double frequency_hz) const {
    return fixed_db(frequency_hz) + rest_.magnitude_db(frequency_hz);
}

void ActuatorModel::prepare(const ProcessSpec& spec, const ActuatorProfile& a) {
    actuator_ = a;
    sample_rate_hz_ = spec.sample_rate_hz;
    erm_ = a.type == ActuatorType::erm;
    follow_ = 1.0 - one_pole_coefficient(erm_spin_time_constant_ms(a), spec.sample_rate_hz);
    const double nyquist_hz = 0.45 * spec.sample_rate_hz;
    resonance_on_ = !erm_ && a.resonance != ResonanceKind::none && a.resonance_hz < nyquist_hz;
    if (resonance_on_)
        resonance_.set(a.resonance == ResonanceKind::low_pass
                           ? BiquadCoefficients::lowpass(a.resonance_hz, a.q, sample_rate_hz_)
                           : BiquadCoefficients::bandpass(a.resonance_hz, a.q, sample_rate_hz_));
    const int sections =
        std::clamp(static_cast<int>(std::lround(a.rolloff_db_per_octave / kDbPerOctavePerSection)),
                   1, kMaxEdgeSections);
    edge_count_ = 0;
    if (!erm_) {
        for (int k = 0; k < sections; ++k) {
            const double q = butterworth_q(2 * sections, k);
            if (!a.dc && a.band_low_hz > 0)
                edges_[static_cast<size_t>(edge_count_++)].set(
                    BiquadCoefficients::highpass(a.band_low_hz, q, sample_rate_hz_));
            if (a.band_high_hz < nyquist_hz)
                edges_[static_cast<size_t>(edge_count_++)].set(
                    BiquadCoefficients::lowpass(a.band_high_hz, q, sample_rate_hz_));
        }
    }
    rest_.prepare(
        spec,
        erm_ ? FittedEq::Design{}
             : FittedEq::fit(sample_rate_hz_, FitBand::octave_beyond(a.band_low_hz, a.band_high_hz),
                             [this](double f) { return actuator_.response_db(f) - fixed_db(f); }));
    reset();
}

void ActuatorModel::reset() noexcept {
    resonance_.reset();
    for (auto& edge : edges_) edge.reset();
    rest_.reset();
    speed_ = phase_ = 0.0;
}

void ActuatorModel::process(const float* drive, float* displacement, int count) noexcept {
    if (!erm_) {
        for (int i = 0; i < count; ++i) {
            double y = drive[i];
            if (resonance_on_) y = resonance_.process(y);
            for (int k = 0; k < edge_count_; ++k) y = edges_[static_cast<size_t>(k)].process(y);
            displacement[i] = static_cast<float>(y);
        }
        rest_.process(displacement, count);
        return;
    }
    const double max_drive = actuator_.max_drive;
    const double low_hz = actuator_.erm_min_drive_hz, high_hz = actuator_.erm_max_drive_hz;
    double speed = speed_, phase = phase_;
    for (int i = 0; i < count; ++i) {
        const double x = std::clamp(drive[i] / max_drive, -1.0, 1.0);
        speed += follow_ * (x - speed);
        if (std::abs(speed) < kStillSpeed) speed = 0.0;
        const double magnitude = std::abs(speed);
        phase += (low_hz + (high_hz - low_hz) * magnitude) / sample_rate_hz_;
        phase -= std::floor(phase);
        displacement[i] = static_cast<float>(magnitude * std::sin(2 * kPi * phase));
    }
    speed_ = speed;
    phase_ = phase;
}

}  // namespace tactus
