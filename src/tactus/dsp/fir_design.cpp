#include "tactus/dsp/fir_design.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {

using Complex = std::complex<double>;

// In-place radix-2 FFT in double precision (inverse: conjugate exponent, unscaled): a design's
// stop band lies below single precision's reach.
void fft(std::vector<Complex>& x, bool inverse) {
    const size_t n = x.size();
    for (size_t i = 1, j = 0; i < n; ++i) {
        size_t bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) std::swap(x[i], x[j]);
    }
    std::vector<Complex> twiddle(n / 2);
    for (size_t k = 0; k < n / 2; ++k)
        twiddle[k] = std::polar(
            1.0, (inverse ? 2 : -2) * kPi * static_cast<double>(k) / static_cast<double>(n));
    for (size_t length = 2; length <= n; length <<= 1) {
        const size_t step = n / length;
        for (size_t start = 0; start < n; start += length)
            for (size_t k = 0; k < length / 2; ++k) {
                const Complex a = x[start + k], b = x[start + k + length / 2] * twiddle[k * step];
                x[start + k] = a + b;
                x[start + k + length / 2] = a - b;
            }
    }
}

}  // namespace

double bessel_i0(double x) {
    double sum = 1, term = 1;
    for (int k = 1; k < 50; ++k) {
        term *= (x / (2.0 * k)) * (x / (2.0 * k));
        sum += term;
    }
    return sum;
}

double kaiser_window(double r, double beta) {
    return bessel_i0(beta * std::sqrt(std::max(0.0, 1 - r * r))) / bessel_i0(beta);
}

std::vector<double> minimum_phase(const std::vector<double>& h, int fft_size, double floor_db) {
    const auto n = static_cast<size_t>(fft_size);
    std::vector<Complex> x(n);
    std::copy(h.begin(), h.end(), x.begin());
    // Folded real cepstrum: log |H| -> its causal part doubled -> exp -> the minimum phase.
    fft(x, false);
    double peak = 0;
    for (const auto& v : x) peak = std::max(peak, std::abs(v));
    const double floor = peak * db_to_gain(floor_db);
    for (auto& v : x) v = std::log(std::max(std::abs(v), floor));
    fft(x, true);
    for (size_t k = 1; k < n / 2; ++k) x[k] *= 2.0;
    for (size_t k = n / 2 + 1; k < n; ++k) x[k] = 0;
    for (auto& v : x) v /= static_cast<double>(n);
    fft(x, false);
    for (auto& v : x) v = std::exp(v);
    fft(x, true);
    std::vector<double> out(h.size());
    for (size_t k = 0; k < out.size(); ++k) out[k] = x[k].real() / static_cast<double>(n);
    return out;
}

}  // namespace tactus
