// FIR design shared by the resamplers (dsp/resampler.hpp, dsp/upsampler.hpp): the Kaiser
// window (Kaiser 1974; Oppenheim & Schafer 7.6) and the minimum-phase filter of a magnitude
// response by the folded real cepstrum (Oppenheim & Schafer 13.9.2). Setup only: both allocate.
#pragma once

#include <vector>

namespace tactus {

// Zeroth-order modified Bessel function of the first kind (power series).
double bessel_i0(double x);

// The Kaiser window at r in [-1, 1] (its centre at 0), shape `beta`; 0 outside.
double kaiser_window(double r, double beta);

// The causal minimum-phase filter with the magnitude response of `h` (its length), computed on
// `fft_size` points (a power of two, dense enough that the cepstrum does not alias); magnitudes
// more than -floor_db below the peak are read as the floor, which keeps the log finite at zeros.
std::vector<double> minimum_phase(const std::vector<double>& h, int fft_size, double floor_db);

}  // namespace tactus
