#include "tactus/export/felt_envelope.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/perception/threshold.hpp"

namespace tactus {

FeltEnvelope::FeltEnvelope(double sample_rate_hz) : sample_rate_hz_(sample_rate_hz) {}

double FeltEnvelope::weight(double frequency_hz) {
    using namespace perception;
    const double f = std::clamp(frequency_hz, kPLowEdgeHz, kPHighEdgeHz);
    return std::pow(10.0, (p_threshold_db(kPBestHz) - p_threshold_db(f)) / 20.0);
}

void FeltEnvelope::write(const float* vibration, int count, double carrier_hz) {
    for (int i = 0; i < count; ++i, ++samples_) {
        const auto step =
            static_cast<size_t>(static_cast<double>(samples_) / sample_rate_hz_ / kStepS);
        if (step >= step_peak_.size()) {
            step_peak_.resize(step + 1, 0.0);
            carrier_hz_.resize(step + 1, carrier_hz);
        }
        step_peak_[step] = std::max(step_peak_[step], static_cast<double>(std::abs(vibration[i])));
        carrier_hz_[step] = carrier_hz;
    }
}

std::vector<double> FeltEnvelope::felt() const {
    const auto n = static_cast<std::ptrdiff_t>(step_peak_.size());
    std::vector<double> out(step_peak_.size());
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        const double f = std::max(carrier_hz_[i], 1.0 / kMaxPeriodS);
        // Half a carrier period either side, at least the step itself.
        const auto half = static_cast<std::ptrdiff_t>(std::lround(0.5 / f / kStepS));
        double peak = 0.0;
        for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, i - half);
             j <= std::min(n - 1, i + half); ++j)
            peak = std::max(peak, step_peak_[j]);
        out[i] = peak * weight(carrier_hz_[i]);
    }
    return out;
}

}  // namespace tactus
