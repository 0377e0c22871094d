// The resamplers' FIR tables generated at build time (fir_tables_generator.cpp) hold exactly what
// the designs compute: every point, tap and delay bit for bit, so the output is the same as when
// each prepare() designed them.
#include <gtest/gtest.h>

#include "tactus/dsp/resampler_kernel.hpp"
#include "tactus/dsp/upsampler_taps.hpp"

namespace tactus {
namespace {

TEST(FirTables, ResamplerKernelsAreTheDesignBitForBit) {
    for (auto band : {Resampler::Band::analysis, Resampler::Band::listening}) {
        const ResamplerKernel designed = design_resampler_kernel(band);
        const ResamplerKernelView table = resampler_kernel_table(band);
        ASSERT_EQ(table.points.size(), designed.points.size());
        for (size_t i = 0; i < table.points.size(); ++i)
            ASSERT_EQ(table.points[i], designed.points[i]) << "point " << i;
        EXPECT_EQ(table.points_per_unit, designed.points_per_unit);
        EXPECT_EQ(table.delay_output_samples, designed.delay_output_samples);
    }
}

TEST(FirTables, UpsamplerTapsAreTheDesignBitForBit) {
    for (int factor = 2; factor <= Upsampler::kMaxFactor; ++factor) {
        const UpsamplerTaps designed = design_upsampler_taps(factor);
        const UpsamplerTaps& table = upsampler_taps_table(factor);
        EXPECT_EQ(table.taps, designed.taps) << "factor " << factor;
        EXPECT_EQ(table.delay_samples, designed.delay_samples) << "factor " << factor;
    }
}

}  // namespace
}  // namespace tactus
