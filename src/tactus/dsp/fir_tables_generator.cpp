// Build-time generator of fir_tables.cpp: the resamplers' minimum-phase FIR designs
// (resampler_kernel.hpp, upsampler_taps.hpp), which depend on no rate or setting, computed once
// here rather than in every prepare() (10^8 instructions each). Values are written as hexadecimal
// floating-point literals: the tables hold exactly what the design computes.
// Usage: tactus_fir_tables OUTPUT.cpp
#include <cstdio>
#include <string>

#include "tactus/dsp/generated_source.hpp"
#include "tactus/dsp/resampler_kernel.hpp"
#include "tactus/dsp/upsampler_taps.hpp"

namespace {

using tactus::Resampler;
using tactus::Upsampler;

void write_kernel(std::FILE* f, const char* name, const tactus::ResamplerKernel& k) {
    std::fprintf(f, "constexpr double %s[] = {\n", name);
    for (double v : k.points) std::fprintf(f, "%a,\n", v);
    std::fprintf(f, "};\n");
}

}  // namespace

int main(int argc, char** argv) {
    return tactus::write_generated_source(argc, argv, [](std::FILE* f) {
        const tactus::ResamplerKernel analysis =
            tactus::design_resampler_kernel(Resampler::Band::analysis);
        const tactus::ResamplerKernel listening =
            tactus::design_resampler_kernel(Resampler::Band::listening);
        std::fprintf(f,
                     "// Generated at build time by fir_tables_generator.cpp: do not edit.\n"
                     "#include \"tactus/dsp/resampler_kernel.hpp\"\n"
                     "#include \"tactus/dsp/upsampler_taps.hpp\"\n\n"
                     "namespace tactus {\nnamespace {\n\n");
        write_kernel(f, "kAnalysisPoints", analysis);
        write_kernel(f, "kListeningPoints", listening);
        std::fprintf(f, "const UpsamplerTaps kUpsamplerTaps[] = {\n{},\n{},\n");
        for (int factor = 2; factor <= Upsampler::kMaxFactor; ++factor) {
            const tactus::UpsamplerTaps t = tactus::design_upsampler_taps(factor);
            std::fprintf(f, "{{{\n");
            for (const auto& row : t.taps) {
                std::fprintf(f, "{{");
                for (float v : row) std::fprintf(f, "%af,", static_cast<double>(v));
                std::fprintf(f, "}},\n");
            }
            std::fprintf(f, "}}, %a},\n", t.delay_samples);
        }
        std::fprintf(f, "};\n\n}  // namespace\n\n");
        std::fprintf(f,
                     "ResamplerKernelView resampler_kernel_table(Resampler::Band band) {\n"
                     "    if (band == Resampler::Band::listening)\n"
                     "        return {kListeningPoints, %d, %a};\n"
                     "    return {kAnalysisPoints, %d, %a};\n}\n\n",
                     listening.points_per_unit, listening.delay_output_samples,
                     analysis.points_per_unit, analysis.delay_output_samples);
        std::fprintf(f,
                     "const UpsamplerTaps& upsampler_taps_table(int factor) {\n"
                     "    return kUpsamplerTaps[factor];\n}\n\n}  // namespace tactus\n");
    });
}
