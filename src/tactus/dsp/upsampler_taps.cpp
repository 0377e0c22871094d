#include "tactus/dsp/upsampler_taps.hpp"

#include <cmath>
#include <vector>

#include "tactus/core/units.hpp"
#include "tactus/dsp/fir_design.hpp"

namespace tactus {
namespace {

constexpr double kKaiserBeta = 7.0;  // ~70 dB stop band at 8 taps per phase
constexpr int kCepstrumSize = 8192;  // dense enough that the cepstrum does not alias
constexpr double kFloorDb = -160;    // re the peak: keeps log() finite at the zeros

// Linear-phase low-pass cut at the internal Nyquist frequency, gain `factor` (interpolation).
std::vector<double> kaiser_lowpass(int factor, int length) {
    std::vector<double> h(static_cast<size_t>(length));
    const double cutoff = 0.5 / factor;  // cycles per output sample
    const double middle = (length - 1) / 2.0;
    for (int n = 0; n < length; ++n) {
        const double t = n - middle;
        const double sinc =
            t == 0.0 ? 1.0 : std::sin(2.0 * kPi * cutoff * t) / (2.0 * kPi * cutoff * t);
        const double r = t / middle;
        h[n] = 2.0 * cutoff * sinc * kaiser_window(r, kKaiserBeta) * factor;
    }
    return h;
}

}  // namespace

UpsamplerTaps design_upsampler_taps(int factor) {
    constexpr int K = Upsampler::kTapsPerPhase;
    std::vector<double> h =
        minimum_phase(kaiser_lowpass(factor, factor * K), kCepstrumSize, kFloorDb);
    // Each phase sums to exactly 1: a constant passes without ripple at the internal rate.
    for (int r = 0; r < factor; ++r) {
        double sum = 0.0;
        for (int i = 0; i < K; ++i) sum += h[i * factor + r];
        for (int i = 0; i < K; ++i) h[i * factor + r] /= sum;
    }
    UpsamplerTaps out;
    double moment = 0.0;
    for (size_t n = 0; n < h.size(); ++n) moment += static_cast<double>(n) * h[n];
    out.delay_samples = moment / factor;  // DC group delay: sum n h[n] / sum h[n], sum = F
    for (int i = 0; i < K; ++i)
        for (int r = 0; r < factor; ++r) out.taps[i][r] = static_cast<float>(h[i * factor + r]);
    return out;
}

}  // namespace tactus
