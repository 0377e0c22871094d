#include "tactus/analysis/pitch_yin.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {

void PitchYin::prepare(const ProcessSpec& spec, const PitchSettings& settings) {
    const double sample_rate_hz = spec.sample_rate_hz;
    const double min_hz = settings.min_hz, max_hz = settings.max_hz;
    sample_rate_hz_ = sample_rate_hz;
    threshold_ = settings.threshold;
    max_lag_ = static_cast<int>(std::ceil(sample_rate_hz / min_hz)) + 1;
    min_lag_ = std::max(2, static_cast<int>(std::floor(sample_rate_hz / max_hz)));
    window_ = max_lag_ + 1;
    fft_.prepare(next_power_of_two(2 * static_cast<int64_t>(window_)));
    signal_.assign(2 * static_cast<size_t>(window_), 0.0f);
    signal_spectrum_.assign(static_cast<size_t>(fft_.bins()), {});
    difference_.assign(static_cast<size_t>(max_lag_) + 2, 0.0);
}

Pitch PitchYin::analyse(const SampleHistory& history) noexcept {
    const int w = window_, n = fft_.size();
    history.read_latest(signal_.data(), 2 * w);

    // c(tau) = sum_{j<w} x[j] x[j+tau], by the spectrum of x times the conjugate spectrum of
    // x's first w samples (no wrap: 2w <= n).
    float* time = fft_.time();
    std::copy(signal_.begin(), signal_.end(), time);
    std::fill(time + 2 * static_cast<std::ptrdiff_t>(w), time + n, 0.0f);
    fft_.forward();
    std::copy_n(fft_.spectrum(), fft_.bins(), signal_spectrum_.begin());
    std::copy_n(signal_.begin(), w, time);
    std::fill(time + w, time + n, 0.0f);
    fft_.forward();
    std::complex<float>* spectrum = fft_.spectrum();
    for (int k = 0; k < fft_.bins(); ++k)
        spectrum[k] = signal_spectrum_[k] * std::conj(spectrum[k]);
    fft_.inverse();
    const double scale = 1.0 / n;

    // d(tau) = e(0) + e(tau) - 2 c(tau), e(tau) = sum_{j<w} x[j+tau]^2 (running sum).
    double energy_0 = 0.0;
    for (int j = 0; j < w; ++j) energy_0 += double(signal_[j]) * signal_[j];
    constexpr double kSilentEnergy = 1e-10;
    if (energy_0 < kSilentEnergy) return {};
    double energy_tau = energy_0;
    difference_[0] = 0.0;
    double running = 0.0;
    int chosen = -1;
    for (int tau = 1; tau <= max_lag_; ++tau) {
        energy_tau += double(signal_[tau + w - 1]) * signal_[tau + w - 1] -
                      double(signal_[tau - 1]) * signal_[tau - 1];
        const double d = std::max(0.0, energy_0 + energy_tau - 2.0 * time[tau] * scale);
        running += d;
        difference_[tau] = running > 0 ? d * tau / running : 1.0;  // cumulative mean normalised
    }
    for (int tau = min_lag_; tau <= max_lag_; ++tau) {
        if (difference_[tau] < threshold_) {
            while (tau + 1 <= max_lag_ && difference_[tau + 1] < difference_[tau]) ++tau;
            chosen = tau;
            break;
        }
    }
    if (chosen < 0) {
        chosen = min_lag_;
        for (int tau = min_lag_; tau <= max_lag_; ++tau)
            if (difference_[tau] < difference_[chosen]) chosen = tau;
    }
    double lag = chosen;
    if (chosen > min_lag_ && chosen < max_lag_) {
        const double a = difference_[chosen - 1], b = difference_[chosen],
                     c = difference_[chosen + 1];
        const double denominator = a - 2 * b + c;
        if (denominator > 0) lag += 0.5 * (a - c) / denominator;
    }
    const double confidence = std::clamp(1.0 - difference_[chosen], 0.0, 1.0);
    if (difference_[chosen] >= threshold_) return {0.0, confidence};
    return {sample_rate_hz_ / lag, confidence};
}

}  // namespace tactus
