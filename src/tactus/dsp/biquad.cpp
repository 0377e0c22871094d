#include "tactus/dsp/biquad.hpp"

namespace tactus {
namespace {

BiquadCoefficients normalised(double b0, double b1, double b2, double a0, double a1, double a2) {
    return {b0 / a0, b1 / a0, b2 / a0, a1 / a0, a2 / a0};
}

}  // namespace

BiquadCoefficients BiquadCoefficients::lowpass(double cutoff_hz, double q, double fs) {
    const double w = 2.0 * kPi * cutoff_hz / fs, cw = std::cos(w), alpha = std::sin(w) / (2 * q);
    return normalised((1 - cw) / 2, 1 - cw, (1 - cw) / 2, 1 + alpha, -2 * cw, 1 - alpha);
}

BiquadCoefficients BiquadCoefficients::highpass(double cutoff_hz, double q, double fs) {
    const double w = 2.0 * kPi * cutoff_hz / fs, cw = std::cos(w), alpha = std::sin(w) / (2 * q);
    return normalised((1 + cw) / 2, -(1 + cw), (1 + cw) / 2, 1 + alpha, -2 * cw, 1 - alpha);
}

BiquadCoefficients BiquadCoefficients::bandpass(double centre_hz, double q, double fs) {
    const double w = 2.0 * kPi * centre_hz / fs, cw = std::cos(w), alpha = std::sin(w) / (2 * q);
    return normalised(alpha, 0, -alpha, 1 + alpha, -2 * cw, 1 - alpha);
}

BiquadCoefficients BiquadCoefficients::peaking(double centre_hz, double q, double gain_db,
                                               double fs) {
    const double a = std::pow(10.0, gain_db / 40.0);
    const double w = 2.0 * kPi * centre_hz / fs, cw = std::cos(w), alpha = std::sin(w) / (2 * q);
    return normalised(1 + alpha * a, -2 * cw, 1 - alpha * a, 1 + alpha / a, -2 * cw, 1 - alpha / a);
}

BiquadCoefficients BiquadCoefficients::low_shelf(double corner_hz, double gain_db, double fs) {
    const double a = std::pow(10.0, gain_db / 40.0);
    const double w = 2.0 * kPi * corner_hz / fs, cw = std::cos(w);
    const double alpha = std::sin(w) / 2.0 * std::sqrt(2.0);  // shelf slope S = 1
    const double r = 2 * std::sqrt(a) * alpha;
    return normalised(a * ((a + 1) - (a - 1) * cw + r), 2 * a * ((a - 1) - (a + 1) * cw),
                      a * ((a + 1) - (a - 1) * cw - r), (a + 1) + (a - 1) * cw + r,
                      -2 * ((a - 1) + (a + 1) * cw), (a + 1) + (a - 1) * cw - r);
}

BiquadCoefficients BiquadCoefficients::high_shelf(double corner_hz, double gain_db, double fs) {
    const double a = std::pow(10.0, gain_db / 40.0);
    const double w = 2.0 * kPi * corner_hz / fs, cw = std::cos(w);
    const double alpha = std::sin(w) / 2.0 * std::sqrt(2.0);
    const double r = 2 * std::sqrt(a) * alpha;
    return normalised(a * ((a + 1) + (a - 1) * cw + r), -2 * a * ((a - 1) + (a + 1) * cw),
                      a * ((a + 1) + (a - 1) * cw - r), (a + 1) - (a - 1) * cw + r,
                      2 * ((a - 1) - (a + 1) * cw), (a + 1) - (a - 1) * cw - r);
}

std::complex<double> BiquadCoefficients::response(double frequency_hz, double fs) const {
    const std::complex<double> z1 = std::polar(1.0, -2.0 * kPi * frequency_hz / fs);
    const std::complex<double> z2 = z1 * z1;
    return (b0 + b1 * z1 + b2 * z2) / (1.0 + a1 * z1 + a2 * z2);
}

}  // namespace tactus
