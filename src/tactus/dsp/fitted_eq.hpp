// A magnitude response drawn to order: a cascade of half-octave peaking biquads across
// [low_hz, high_hz] plus an overall gain, the section gains fitted to a target curve (dB) by
// damped Gauss-Newton least squares in dB on a log-frequency grid (the "accurate graphic
// equaliser" design idea of Välimäki & Liski 2017). Used by the flattening filter (a perception
// target) and the actuator compensation (an inverse actuator response).
// A new design (a control thread fits it: fit() allocates) is taken live by glide_to() on the
// audio thread: the coefficients move linearly from the old design to the new one, every
// kGlideStep samples, keeping the filter states. The sections' centres and Q depend only on the
// band and rate, and every stable biquad's (a1, a2) lies in one convex triangle, so every
// intermediate filter is stable.
#pragma once

#include <algorithm>
#include <array>
#include <functional>
#include <vector>

#include "tactus/dsp/biquad.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

// The band a fit spans.
struct FitBand {
    static constexpr double kLowestHz = 1.0;
    static constexpr double kWidestRatio = 181.0;  // 7.5 octaves: 16 half-octave sections

    double low_hz = 20;
    double high_hz = 1000;

    // An octave beyond [low_hz, high_hz] on each side (a target that holds its edge values
    // there keeps the response from drifting just outside), within what the sections reach.
    static FitBand octave_beyond(double low_hz, double high_hz) {
        const double low = std::max(low_hz / 2, kLowestHz);
        return {.low_hz = low, .high_hz = std::min(high_hz * 2, low * kWidestRatio)};
    }
};

class FittedEq {
  public:
    static constexpr int kMaxSections = 16;
    static constexpr int kGridPoints = 96;
    static constexpr int kGlideStep = 16;  // samples between coefficient steps of a glide

    // The result of a fit: what the filter runs with. Copied without allocation.
    struct Design {
        std::array<BiquadCoefficients, kMaxSections> sections{};
        int count = 0;
        double gain = 1.0;
    };

    // The log-frequency grid the fit is made on (and a target's extremes are best taken on).
    static std::vector<double> grid(const FitBand& band);
    static double highest_fitted_hz(double high_hz, double sample_rate_hz) {
        return std::min(high_hz, 0.45 * sample_rate_hz);
    }

    // Allocates. The target is sampled on the grid of the band, its top at most
    // highest_fitted_hz(). Any thread but an audio one: a fit with the same rate, band and
    // target samples as one made before in the process returns that one's design.
    static Design fit(double sample_rate_hz, const FitBand& band,
                      const std::function<double(double frequency_hz)>& target_db);
    // The rate magnitude_db() reads, then set() and reset().
    void prepare(const ProcessSpec& spec, const Design& design) noexcept {
        sample_rate_hz_ = spec.sample_rate_hz;
        set(design);
        reset();
    }
    int latency() const { return 0; }  // minimum phase
    // Runs `design` from now on (control or audio thread, between process() calls).
    void set(const Design& design) noexcept;
    // Audio thread: moves to `design` over `samples` samples (at once when 0). The design must
    // come from fit() at the same rate and band.
    void glide_to(const Design& design, int samples) noexcept;
    void reset() noexcept;
    void process(float* samples, int count) noexcept;
    double magnitude_db(double frequency_hz) const;  // what it achieves now

  private:
    static Design fit_on_grid(double sample_rate_hz, const FitBand& band,
                              const std::vector<double>& frequencies,
                              const std::vector<double>& target);
    void step_glide() noexcept;
    double sample_rate_hz_ = 48000;
    std::array<Biquad, kMaxSections> sections_;
    int count_ = 0;
    double gain_ = 1.0;
    Design from_, to_;     // a glide's ends
    int glide_steps_ = 0;  // coefficient steps a glide takes
    int glide_done_ = 0;   // steps taken
    int until_step_ = 0;   // samples until the next step
};

}  // namespace tactus
