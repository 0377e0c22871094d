#include "tactus/analysis/stft_frame.hpp"

#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/core/vector_clones.hpp"

namespace tactus {

void StftFrame::prepare(int window_samples, double sample_rate_hz) {
    fft_.prepare(window_samples);
    window_.resize(static_cast<size_t>(window_samples));
    double window_sum = 0;
    for (int i = 0; i < window_samples; ++i) {
        window_[i] = static_cast<float>(0.5 - 0.5 * std::cos(2.0 * kPi * i / window_samples));
        window_sum += window_[i];
    }
    // A sine of amplitude A gives |X| = A * sum(w) / 2 at its bin.
    const auto scale = static_cast<float>(2.0 / window_sum);
    for (auto& w : window_) w *= scale;
    magnitudes_.assign(static_cast<size_t>(fft_.bins()), 0.0f);
    powers_.assign(static_cast<size_t>(fft_.bins()), 0.0f);
    bin_hz_ = sample_rate_hz / window_samples;
}

TACTUS_VECTOR_CLONES void StftFrame::analyse(const SampleHistory& history) noexcept {
    const int n = fft_.size();
    float* time = fft_.time();
    history.read_latest(time, n);
    for (int i = 0; i < n; ++i) time[i] *= window_[i];
    fft_.forward();
    const std::complex<float>* x = fft_.spectrum();
    for (int k = 0; k < fft_.bins(); ++k) {
        const float re = x[k].real(), im = x[k].imag();
        powers_[k] = re * re + im * im;
        magnitudes_[k] = std::sqrt(powers_[k]);
    }
}

}  // namespace tactus
