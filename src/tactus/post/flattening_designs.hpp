// The flattening filter's designs made at build time (flattening_designs_generator.cpp writes
// the generated flattening_designs.cpp): the default settings' inputs at the internal rates of
// the usual output rates (44.1 to 192 kHz), so that a process's first engine takes its design
// instead of fitting it (8 M instructions).
#pragma once

#include "tactus/post/flattening_filter.hpp"

namespace tactus {

struct BuiltFlatteningDesign {
    double sample_rate_hz;  // internal rate
    FlatteningFilter::Design design;
};
extern const BuiltFlatteningDesign kFlatteningDesigns[];
extern const int kFlatteningDesignEntries;

}  // namespace tactus
