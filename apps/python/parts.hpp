// Drum parts as Python sees them: by name (tactus.drum_parts, kDrumPartNames), so a column of
// them is a numpy array of strings (frames["part"] == "snare").
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "tactus/analysis/drum_part.hpp"

namespace tactus::python {

// ("kick", "snare", "hat", "other").
inline pybind11::tuple drum_part_names() {
    pybind11::tuple names(kDrumPartNames.size());
    for (size_t i = 0; i < kDrumPartNames.size(); ++i)
        names[i] = pybind11::str(kDrumPartNames[i].data(), kDrumPartNames[i].size());
    return names;
}

// An array of DrumPart indices (any numeric dtype) as the array of their names.
inline pybind11::object part_names(const pybind11::handle& indices) {
    const pybind11::module_ numpy = pybind11::module_::import("numpy");
    return numpy.attr("array")(drum_part_names())[indices.attr("astype")(numpy.attr("intp"))];
}

}  // namespace tactus::python
