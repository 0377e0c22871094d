// Vibrotactile detection threshold of the Pacinian (P) channel vs frequency, dB re 1 um peak
// displacement (thenar eminence, 2.9 cm^2 contactor, 1 s bursts). Shape from perception.md:
// flat below 40 Hz is not P's but NPI's region; above it the curve falls 12 dB/octave to a
// minimum near 250 Hz (Verrillo 1963) and rises ~9 dB/octave above (Verrillo 1966):
//   T_P(f) = T_min + 10 log10( (3/7)(f_m/f)^4 + (4/7)(f/f_m)^3 ),  f_m = 250 Hz.
// T_min = -20 dB is a recalled level (+-5 dB); shapes are what the filters depend on.
#pragma once

#include <cmath>

namespace tactus::perception {

constexpr double kPBestHz = 250.0;     // f_m [derived, perception.md]
constexpr double kPMinimumDb = -20.0;  // T_Pmin [recalled, +-5 dB]
constexpr double kPLowEdgeHz = 40.0;   // P channel range 40-500 Hz (paper Table 1)
constexpr double kPHighEdgeHz = 500.0;

inline double p_threshold_db(double frequency_hz) {
    const double r = kPBestHz / frequency_hz;
    return kPMinimumDb + 10.0 * std::log10((3.0 / 7.0) * r * r * r * r + (4.0 / 7.0) / (r * r * r));
}

}  // namespace tactus::perception
