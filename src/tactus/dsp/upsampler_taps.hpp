// The Upsampler's polyphase taps (dsp/upsampler.hpp) for each factor: a Kaiser-windowed-sinc
// low-pass at the internal Nyquist frequency, made minimum phase (homomorphic design, Oppenheim
// & Schafer 2010, §13.9), each phase summing to 1. They depend on the factor alone, so they are
// designed once, at build time (fir_tables_generator.cpp writes the generated fir_tables.cpp);
// the design stays here for the generator and the tests that hold the tables to it.
#pragma once

#include <array>

#include "tactus/dsp/upsampler.hpp"

namespace tactus {

struct UpsamplerTaps {
    // taps[i][r] = h[i F + r], F the factor.
    std::array<std::array<float, Upsampler::kMaxFactor>, Upsampler::kTapsPerPhase> taps{};
    double delay_samples = 0;  // group delay at low frequencies, output samples
};

// Setup only: allocates. factor 2 ... Upsampler::kMaxFactor.
UpsamplerTaps design_upsampler_taps(int factor);

// The generated table (fir_tables.cpp): what design_upsampler_taps() gives; factor 1: none.
const UpsamplerTaps& upsampler_taps_table(int factor);

}  // namespace tactus
