#include "tactus/post/band_limit.hpp"

#include <algorithm>
#include <stdexcept>

#include "tactus/dsp/biquad_cascade.hpp"

namespace tactus {

void BandLimit::prepare(const ProcessSpec& spec, const BandEdges& band) {
    const int order = band.order;
    if (order < 2 || order > kMaxOrder || order % 2 != 0)
        throw std::invalid_argument("band-limit order must be 2, 4, 6 or 8");
    const double sample_rate_hz = spec.sample_rate_hz, low_hz = band.low_hz, high_hz = band.high_hz;
    sample_rate_hz_ = sample_rate_hz;
    const int per_side = order / 2;
    count_ = 0;
    for (int k = 0; k < per_side; ++k)
        sections_[count_++].set(
            BiquadCoefficients::highpass(low_hz, butterworth_q(order, k), sample_rate_hz));
    // A low-pass near Nyquist would be meaningless; the band then ends at Nyquist.
    if (band.low_pass && high_hz < 0.45 * sample_rate_hz)
        for (int k = 0; k < per_side; ++k)
            sections_[count_++].set(
                BiquadCoefficients::lowpass(high_hz, butterworth_q(order, k), sample_rate_hz));
    reset();
}

void BandLimit::reset() noexcept {
    for (auto& s : sections_) s.reset();
}

void BandLimit::process(float* samples, int count) noexcept {
    process_cascade(sections_.data(), count_, samples, count);
}

double BandLimit::magnitude_db(double frequency_hz) const {
    double db = 0.0;
    for (int s = 0; s < count_; ++s)
        db += sections_[s].coefficients().magnitude_db(frequency_hz, sample_rate_hz_);
    return db;
}

}  // namespace tactus
