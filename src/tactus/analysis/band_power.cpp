#include "tactus/analysis/band_power.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus {

void BandPower::prepare(Band band, double sample_rate_hz, int window_frames) {
    active_ = band == Band::low || sample_rate_hz / 2 >= kHighEdgeHz + kMinWidthHz;
    for (int s = 0; s < 2; ++s)
        sections_[s].set(band == Band::low ? BiquadCoefficients::lowpass(
                                                 kLowEdgeHz, butterworth_q(4, s), sample_rate_hz)
                                           : BiquadCoefficients::highpass(
                                                 kHighEdgeHz, butterworth_q(4, s), sample_rate_hz));
    energy_.assign(static_cast<size_t>(std::max(1, window_frames)), 0.0);
    samples_.assign(energy_.size(), 0);
    // Frame j back (0: the newest) spans (j, j + 1) of the window's window_frames: its Hann weight
    // at its centre, squared as the spectrum's power is.
    weight_.resize(energy_.size());
    for (size_t j = 0; j < weight_.size(); ++j) {
        const double w = 0.5 - 0.5 * std::cos(2 * kPi * (static_cast<double>(j) + 0.5) /
                                              static_cast<double>(weight_.size()));
        weight_[j] = w * w;
    }
    reset();
}

void BandPower::reset() noexcept {
    for (auto& section : sections_) section.reset();
    std::fill(energy_.begin(), energy_.end(), 0.0);
    std::fill(samples_.begin(), samples_.end(), 0);
    position_ = 0;
}

void BandPower::process(const float* samples, int count) noexcept {
    if (!active_) return;
    double energy = 0;
    for (int i = 0; i < count; ++i) {
        const double y = sections_[1].process(sections_[0].process(samples[i]));
        energy += y * y;
    }
    energy_[position_] += energy;
    samples_[position_] += count;
}

BandPower::Power BandPower::frame() noexcept {
    const int frames = static_cast<int>(energy_.size());
    double energy = 0, samples = 0, weighted_energy = 0, weighted_samples = 0;
    for (int j = 0; j < frames; ++j) {
        const int slot = (position_ + frames - j) % frames;
        energy += energy_[slot];
        samples += samples_[slot];
        weighted_energy += weight_[j] * energy_[slot];
        weighted_samples += weight_[j] * samples_[slot];
    }
    position_ = (position_ + 1) % static_cast<int>(energy_.size());
    energy_[position_] = 0;
    samples_[position_] = 0;
    if (samples <= 0) return {};
    return {.mean = energy / samples, .hann = weighted_energy / weighted_samples};
}

}  // namespace tactus
