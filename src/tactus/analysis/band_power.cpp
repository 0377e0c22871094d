#include "tactus/analysis/band_power.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/dsp/biquad_cascade.hpp"

namespace tactus {

void BandPower::prepare(Band band, double sample_rate_hz, int window_frames) {
    active_ = band == Band::low || sample_rate_hz / 2 >= kHighTopHz * kTopMargin;
    section_count_ = band == Band::low ? kLowSections : kHighSections;
    for (int s = 0; s < 2; ++s) {
        const double q = butterworth_q(4, s);
        if (band == Band::low) {
            sections_[s].set(BiquadCoefficients::lowpass(kLowEdgeHz, q, sample_rate_hz));
        } else if (active_) {
            sections_[s].set(BiquadCoefficients::highpass(kHighEdgeHz, q, sample_rate_hz));
            sections_[s + 2].set(BiquadCoefficients::lowpass(kHighTopHz, q, sample_rate_hz));
        }
    }
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
    // Summed sample by sample into the frame's total: the same order for any block split.
    Energy energy = open();
    const auto input = [&](int i) { return static_cast<double>(samples[i]); };
    const auto add = [&](int, double y) { energy.take(y * y); };
    if (section_count_ == kLowSections)
        cascade_each<kLowSections>(sections_.data(), count, input, add);
    else
        cascade_each<kHighSections>(sections_.data(), count, input, add);
    close(energy, count);
}

void BandPower::close(Energy energy, int count) noexcept {
    energy_[static_cast<size_t>(position_)] = energy.sum;
    samples_[static_cast<size_t>(position_)] += count;
}

BandPower::Power BandPower::frame() noexcept {
    const int frames = static_cast<int>(energy_.size());
    double energy = 0, samples = 0, weighted_energy = 0, weighted_samples = 0;
    // Frame j back is in slot position_ - j, wrapping from 0 to the end (no division a frame).
    for (int j = 0, slot = position_; j < frames; ++j, slot = slot == 0 ? frames - 1 : slot - 1) {
        energy += energy_[slot];
        samples += samples_[slot];
        weighted_energy += weight_[j] * energy_[slot];
        weighted_samples += weight_[j] * samples_[slot];
    }
    const double newest = samples_[position_] > 0 ? energy_[position_] / samples_[position_] : 0.0;
    position_ = (position_ + 1) % static_cast<int>(energy_.size());
    energy_[position_] = 0;
    samples_[position_] = 0;
    if (samples <= 0) return {};
    return {.mean = energy / samples, .hann = weighted_energy / weighted_samples, .newest = newest};
}

}  // namespace tactus
