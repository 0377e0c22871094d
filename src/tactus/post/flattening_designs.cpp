// Where a flattening filter's design comes from: the build's table, the process's memo, or made
// now (apart from the design itself, which the build-time generator runs).
#include "tactus/post/flattening_designs.hpp"

#include <utility>

#include "tactus/dsp/design_memo.hpp"

namespace tactus {

FlatteningFilter::Design FlatteningFilter::design(double sample_rate_hz,
                                                  const FlatteningDesign& inputs) {
    for (int i = 0; i < kFlatteningDesignEntries; ++i) {
        const BuiltFlatteningDesign& built = kFlatteningDesigns[i];
        if (built.sample_rate_hz == sample_rate_hz && built.design.inputs == inputs)
            return built.design;
    }
    static DesignMemo<std::pair<double, FlatteningDesign>, Design> designs;
    return designs.get({sample_rate_hz, inputs},
                       [&] { return make_design(sample_rate_hz, inputs); });
}

void FlatteningFilter::prepare(const ProcessSpec& spec, const FlatteningDesign& inputs) {
    const Design d = design(spec.sample_rate_hz, inputs);
    design_ = d.inputs;
    reference_db_ = d.reference_db;
    eq_.prepare(spec, d.eq);
}

}  // namespace tactus
