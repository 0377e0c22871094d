// The Python module tactus._tactus (apps/python/tactus/__init__.py re-exports it): the engine,
// the offline commands and the perception model on numpy arrays (pybind11).
#include <pybind11/pybind11.h>

#include "settings.hpp"

namespace py = pybind11;

namespace tactus::python {
void add_offline(py::module_& m);
void add_engine(py::module_& m);
void add_perception(py::module_& m);
}  // namespace tactus::python

#include <pybind11/stl.h>

#include "tactus/io/preset.hpp"

namespace tactus::python {
namespace {

// The parameter table as a list of dicts, for listing and generating views of it.
py::list params() {
    py::list out;
    const Settings defaults;
    for (const ParamSpec& s : param_table()) {
        py::dict d;
        d["key"] = std::string(s.key);
        d["name"] = identifier_of(s);
        d["id"] = s.id;
        d["type"] = std::string(kParamTypeNames[static_cast<int>(s.type)]);
        d["unit"] = std::string(s.unit);
        d["min"] = s.min;
        d["max"] = s.max;
        d["default"] = defaults[s.param];
        d["curve"] = s.curve == ParamCurve::log ? "log" : "lin";
        d["live"] = s.change == ParamChange::live;
        d["smoothing_ms"] = s.smoothing_ms;
        d["help"] = std::string(s.help);
        py::list choices;
        for (auto c : s.choices) choices.append(std::string(c));
        d["choices"] = choices;
        out.append(d);
    }
    return out;
}

py::list presets() {
    py::list out;
    for (const PresetInfo& p : list_presets()) {
        py::dict d;
        d["name"] = p.name;
        d["path"] = p.path.string();
        d["description"] = p.description;
        out.append(d);
    }
    return out;
}

}  // namespace
}  // namespace tactus::python

PYBIND11_MODULE(_tactus, m) {
    using namespace tactus::python;
    m.doc() = "tactus: music to vibrotactile feedback (the engine, offline commands, perception)";
    m.attr("__version__") = TACTUS_VERSION;
    m.def("params", &params,
          "Every parameter of the one table: key, Python name, stable id, type, unit, range, "
          "default, curve, live or structural, smoothing, help, choices.");
    m.def("presets", &presets, "The presets found (name, path, description), as `tactus presets`.");
    add_offline(m);
    add_engine(m);
    add_perception(m);
}
