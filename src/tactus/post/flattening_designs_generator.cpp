// Build-time generator of flattening_designs.cpp (flattening_designs.hpp): the flattening
// filter's design for the default settings at the internal rate of each usual output rate, made
// by FlatteningFilter::make_design and written as hexadecimal floating-point literals (exactly
// what it computes). Usage: tactus_flattening_designs OUTPUT.cpp
#include <cstdio>
#include <vector>

#include "tactus/dsp/generated_source.hpp"
#include "tactus/engine/pipeline.hpp"
#include "tactus/post/flattening_inputs.hpp"

namespace {

constexpr double kOutputRatesHz[] = {44100, 48000, 88200, 96000, 176400, 192000};

}  // namespace

int main(int argc, char** argv) {
    return tactus::write_generated_source(argc, argv, [](std::FILE* f) {
        using tactus::FlatteningFilter;
        const tactus::FlatteningDesign inputs = tactus::flattening_inputs(tactus::Settings{});
        std::vector<double> rates;
        for (double output_hz : kOutputRatesHz) {
            const double rate = output_hz / tactus::Pipeline::rate_divisor_for(output_hz);
            bool seen = false;
            for (double r : rates) seen = seen || r == rate;
            if (!seen) rates.push_back(rate);
        }
        std::fprintf(f,
                     "// Generated at build time by flattening_designs_generator.cpp: do not "
                     "edit.\n#include \"tactus/post/flattening_designs.hpp\"\n\n"
                     "namespace tactus {\n\nconst BuiltFlatteningDesign kFlatteningDesigns[] = "
                     "{\n");
        for (double rate : rates) {
            const FlatteningFilter::Design d = FlatteningFilter::make_design(rate, inputs);
            const tactus::FlatteningDesign& in = d.inputs;
            std::fprintf(f, "{%a, {{%a, %a, %a, %a, %a, %a}, %a, {{{\n", rate, in.low_hz,
                         in.high_hz, in.strength, in.range_db, in.contact_area_cm2, in.level_db,
                         d.reference_db);
            for (const tactus::BiquadCoefficients& c : d.eq.sections)
                std::fprintf(f, "{%a, %a, %a, %a, %a},\n", c.b0, c.b1, c.b2, c.a1, c.a2);
            std::fprintf(f, "}}, %d, %a}}},\n", d.eq.count, d.eq.gain);
        }
        std::fprintf(f, "};\nconst int kFlatteningDesignEntries = %zu;\n\n}  // namespace tactus\n",
                     rates.size());
    });
}
