// Unit conversions shared by every stage. Names carry units: _db, _hz, _ms, _s, _samples.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>

namespace tactus {

inline double db_to_gain(double db) {
    return std::pow(10.0, db / 20.0);
}
inline double gain_to_db(double gain) {
    return 20.0 * std::log10(gain);
}
inline double power_to_db(double power) {
    return 10.0 * std::log10(power);
}

inline int64_t ms_to_samples(double ms, double sample_rate_hz) {
    return static_cast<int64_t>(std::llround(ms * 1e-3 * sample_rate_hz));
}

// One-pole smoothing coefficient for a time constant, applied once per `step_samples`.
inline double one_pole_coefficient(double time_constant_ms, double sample_rate_hz,
                                   double step_samples = 1.0) {
    if (time_constant_ms <= 0.0) return 0.0;
    return std::exp(-step_samples / (time_constant_ms * 1e-3 * sample_rate_hz));
}

// Smallest power of two >= n.
inline int next_power_of_two(int64_t n) {
    int p = 1;
    while (p < n) p <<= 1;
    return p;
}

// An even size with no prime factor above 5: FFTW transforms it about as fast as a power of two.
inline bool is_fast_fft_size(int64_t n) {
    if (n < 2 || n % 2 != 0) return false;
    for (const int64_t p : {2, 3, 5})
        while (n % p == 0) n /= p;
    return n == 1;
}

// The fast FFT size nearest to n (the smaller on a tie): an FFT window within 4 % of the
// duration asked for any n >= 24.
inline int nearest_fft_size(int64_t n) {
    for (int64_t d = 0;; ++d) {
        if (is_fast_fft_size(n - d)) return static_cast<int>(n - d);
        if (is_fast_fft_size(n + d)) return static_cast<int>(n + d);
    }
}

// The smallest fast FFT size >= n: a window of n samples zero-padded by at most a few percent
// (the next power of two pads 17 640 to 32 768).
inline int fft_size_at_least(int64_t n) {
    while (!is_fast_fft_size(n)) ++n;
    return static_cast<int>(n);
}

constexpr double kPi = 3.14159265358979323846;

// The largest float not above x: float samples that must respect a bound given in double.
inline float float_at_most(double x) {
    const auto f = static_cast<float>(x);
    return f > x ? std::nextafter(f, -HUGE_VALF) : f;
}

}  // namespace tactus
