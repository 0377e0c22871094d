// The Resampler's continuous-time kernel (dsp/resampler.hpp): a Kaiser-windowed sinc made
// minimum phase by the folded real cepstrum, sampled points_per_unit times per sample of the
// lower rate. Rate-independent, so it is designed once, at build time (fir_tables_generator.cpp
// writes the generated fir_tables.cpp); the design stays here for the generator and the tests
// that hold the tables to it.
#pragma once

#include <span>
#include <vector>

#include "tactus/dsp/resampler.hpp"

namespace tactus {

// A kernel as the resampler reads it: unit sum over the points divided by points_per_unit (unit
// DC gain in continuous time); the delay of its energy centroid in samples of the lower rate.
struct ResamplerKernelView {
    std::span<const double> points;
    int points_per_unit = 1;
    double delay_output_samples = 0;
};

struct ResamplerKernel {
    std::vector<double> points;
    int points_per_unit = 1;
    double delay_output_samples = 0;
    ResamplerKernelView view() const { return {points, points_per_unit, delay_output_samples}; }
};

// Setup only: allocates, and takes 10^8 (analysis) to 10^9 (listening) instructions.
ResamplerKernel design_resampler_kernel(Resampler::Band band);

// The generated tables (fir_tables.cpp): what design_resampler_kernel() gives, computed once.
ResamplerKernelView resampler_kernel_table(Resampler::Band band);

}  // namespace tactus
