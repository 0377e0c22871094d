#include "tactus/analysis/high_band.hpp"

#include <algorithm>
#include <numeric>

namespace tactus {

void HighBand::prepare(double sample_rate_hz, int window_frames) {
    active_ = sample_rate_hz / 2 >= kEdgeHz + kMinWidthHz;
    for (int s = 0; s < 2; ++s)
        sections_[s].set(
            BiquadCoefficients::highpass(kEdgeHz, butterworth_q(4, s), sample_rate_hz));
    energy_.assign(static_cast<size_t>(std::max(1, window_frames)), 0.0);
    samples_.assign(energy_.size(), 0);
    reset();
}

void HighBand::reset() noexcept {
    for (auto& section : sections_) section.reset();
    std::fill(energy_.begin(), energy_.end(), 0.0);
    std::fill(samples_.begin(), samples_.end(), 0);
    position_ = 0;
}

void HighBand::process(const float* samples, int count) noexcept {
    if (!active_) return;
    double energy = 0;
    for (int i = 0; i < count; ++i) {
        const double y = sections_[1].process(sections_[0].process(samples[i]));
        energy += y * y;
    }
    energy_[position_] += energy;
    samples_[position_] += count;
}

double HighBand::frame() noexcept {
    const double energy = std::accumulate(energy_.begin(), energy_.end(), 0.0);
    const int samples = std::accumulate(samples_.begin(), samples_.end(), 0);
    position_ = (position_ + 1) % static_cast<int>(energy_.size());
    energy_[position_] = 0;
    samples_[position_] = 0;
    return samples > 0 ? energy / samples : 0.0;
}

}  // namespace tactus
