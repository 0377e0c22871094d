#include "tactus/post/erm_drive.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {
constexpr double kSinePeakOverMean = kPi / 2;  // a sine's peak over its rectified mean
constexpr double kSilentDrive = 1e-9;          // below it the drive is 0: silence stays silent
}  // namespace

void ErmDrive::prepare(const ProcessSpec& spec, double spin_time_constant_ms) {
    envelope_.set(
        BiquadCoefficients::lowpass(kEnvelopeHz, butterworth_q(2, 0), spec.sample_rate_hz));
    follow_ = 1.0 - one_pole_coefficient(spin_time_constant_ms, spec.sample_rate_hz);
    reset();
}

void ErmDrive::reset() noexcept {
    envelope_.reset();
    speed_ = 0.0;
}

void ErmDrive::process(float* samples, int count, double ceiling) noexcept {
    double speed = speed_;
    for (int i = 0; i < count; ++i) {
        const double target =
            std::clamp(kSinePeakOverMean * envelope_.process(std::abs(samples[i])), 0.0, ceiling);
        // The drive that brings the speed to the target in one sample, as far as it may go.
        double drive = std::clamp(speed + (target - speed) / follow_, -ceiling, ceiling);
        speed += follow_ * (drive - speed);
        if (std::abs(drive) < kSilentDrive && std::abs(speed) < kSilentDrive) drive = speed = 0;
        samples[i] = static_cast<float>(drive);
    }
    speed_ = speed;
}

}  // namespace tactus
