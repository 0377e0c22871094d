#include "tactus/dsp/upsampler.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

void Upsampler::prepare(const ProcessSpec& spec, int factor) {
    if (factor < 1 || factor > kMaxFactor)
        throw std::invalid_argument("upsampling factor must be 1-16");
    factor_ = factor;
    taps_ = {};
    delay_samples_ = 0.0;
    if (factor > 1) {  // factor 1 copies: no filter
        std::vector<double> h =
            minimum_phase(kaiser_lowpass(factor, factor * kTapsPerPhase), kCepstrumSize, kFloorDb);
        // Each phase sums to exactly 1: a constant passes without ripple at the internal rate.
        for (int r = 0; r < factor; ++r) {
            double sum = 0.0;
            for (int i = 0; i < kTapsPerPhase; ++i) sum += h[i * factor + r];
            for (int i = 0; i < kTapsPerPhase; ++i) h[i * factor + r] /= sum;
        }
        double moment = 0.0;
        for (size_t n = 0; n < h.size(); ++n) moment += static_cast<double>(n) * h[n];
        delay_samples_ = moment / factor;  // DC group delay: sum n h[n] / sum h[n], sum = F
        for (int i = 0; i < kTapsPerPhase; ++i)
            for (int r = 0; r < factor; ++r) taps_[i][r] = static_cast<float>(h[i * factor + r]);
    }
    line_.assign(static_cast<size_t>(kTapsPerPhase + internal_spec(spec, factor).max_block), 0.0f);
    reset();
}

void Upsampler::reset() noexcept {
    std::fill(line_.begin(), line_.end(), 0.0f);
    phase_ = 0;
}

void Upsampler::process(const float* internal, int internal_count, float* out, int count) noexcept {
    constexpr int K = kTapsPerPhase;
    if (factor_ == 1) {
        std::copy_n(internal, count, out);
        return;
    }
    std::copy_n(internal, internal_count, line_.data() + K);
    // line_[K - 1 + j] is the j-th internal sample at or after the first output's time.
    const float* x = line_.data() + K - (phase_ != 0 ? 1 : 0);
    int r = phase_;
    for (int done = 0; done < count; ++x) {
        std::array<float, kMaxFactor> y{};
        for (int i = 0; i < K; ++i) {
            const float xi = x[-i];
            for (int p = 0; p < factor_; ++p) y[p] += xi * taps_[i][p];
        }
        const int n = std::min(factor_ - r, count - done);
        std::copy_n(y.data() + r, n, out + done);
        done += n;
        r = (r + n) % factor_;
    }
    phase_ = r;
    std::copy_n(line_.data() + internal_count, K, line_.data());
}

}  // namespace tactus
