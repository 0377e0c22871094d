// Second-order IIR section, transposed direct form II in double precision (stable at 20 Hz even
// at 192 kHz). Designs follow R. Bristow-Johnson, "Audio EQ Cookbook"; the Butterworth and
// bilinear forms are the textbook ones.
#pragma once

#include <cmath>
#include <complex>
#include <utility>

#include "tactus/core/units.hpp"

namespace tactus {

struct BiquadCoefficients {
    double b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0;  // a0 normalised to 1

    static BiquadCoefficients lowpass(double cutoff_hz, double q, double sample_rate_hz);
    static BiquadCoefficients highpass(double cutoff_hz, double q, double sample_rate_hz);
    // Band-pass with 0 dB at the centre: a driven resonance's velocity, 1 / |1 + jQ(x - 1/x)|.
    static BiquadCoefficients bandpass(double centre_hz, double q, double sample_rate_hz);
    static BiquadCoefficients peaking(double centre_hz, double q, double gain_db,
                                      double sample_rate_hz);
    static BiquadCoefficients low_shelf(double corner_hz, double gain_db, double sample_rate_hz);
    static BiquadCoefficients high_shelf(double corner_hz, double gain_db, double sample_rate_hz);

    // Complex response at a frequency.
    std::complex<double> response(double frequency_hz, double sample_rate_hz) const;
    double magnitude_db(double frequency_hz, double sample_rate_hz) const {
        return gain_to_db(std::abs(response(frequency_hz, sample_rate_hz)));
    }
};

class Biquad {
  public:
    void set(const BiquadCoefficients& c) { c_ = c; }
    const BiquadCoefficients& coefficients() const { return c_; }
    void reset() noexcept { s1_ = s2_ = 0.0; }
    std::pair<double, double> state() const noexcept { return {s1_, s2_}; }
    void set_state(std::pair<double, double> s) noexcept { s1_ = s.first, s2_ = s.second; }

    double process(double x) noexcept {
        const double y = c_.b0 * x + s1_;
        s1_ = c_.b1 * x - c_.a1 * y + s2_;
        s2_ = c_.b2 * x - c_.a2 * y;
        return y;
    }

  private:
    BiquadCoefficients c_;
    double s1_ = 0, s2_ = 0;
};

// Q of the k-th section of an order-n Butterworth made of biquads (n even).
inline double butterworth_q(int order, int section) {
    return 1.0 / (2.0 * std::cos(kPi * (2.0 * section + 1.0) / (2.0 * order)));
}

}  // namespace tactus
