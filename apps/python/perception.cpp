// The perception model for Python (perception/*.hpp, paper §3.5 and §5): the four channels of
// touch, their threshold curves with contact area and duration, sensation level and how channels
// combine, vectorised over numpy arrays of frequencies and levels.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

#include "tactus/perception/sensation.hpp"

namespace py = pybind11;

namespace tactus::python {
namespace {

using namespace tactus::perception;

Channel channel_named(const std::string& name) {
    std::string known;
    for (const ChannelInfo& c : kChannels) {
        if (c.name == name) return c.channel;
        known.append(known.empty() ? "" : ", ").append(c.name);
    }
    throw py::value_error(fmt::format("unknown channel '{}' (known: {})", name, known));
}

Stimulus stimulus(double contact_area_cm2, double duration_s) {
    if (!(contact_area_cm2 > 0) || !(duration_s > 0))
        throw py::value_error(
            fmt::format("contact_area_cm2 = {} and duration_s = {}: both must be above 0",
                        contact_area_cm2, duration_s));
    return {.contact_area_cm2 = contact_area_cm2, .duration_s = duration_s};
}

// f applied to every element of `x` (any shape); a float for a scalar.
template <typename F>
py::object map_array(const py::handle& x, F f) {
    const auto in = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(x);
    if (!in) throw py::value_error("expected a number or an array of numbers");
    py::array_t<double> out(std::vector<py::ssize_t>(in.shape(), in.shape() + in.ndim()));
    const double* from = in.data();
    double* to = out.mutable_data();
    for (py::ssize_t i = 0; i < in.size(); ++i) to[i] = f(from[i]);
    if (in.ndim() == 0) return py::float_(to[0]);
    return py::object(std::move(out));
}

// A frequency the threshold curves are defined at: above 0 Hz and finite (0 gives an infinite
// threshold, below 0 NaN).
double checked_frequency_hz(double frequency_hz) {
    if (!(frequency_hz > 0) || !std::isfinite(frequency_hz))
        throw py::value_error(fmt::format(
            "frequency_hz = {} is out of range: must be above 0 Hz and finite", frequency_hz));
    return frequency_hz;
}

// f applied to every frequency of `frequency_hz` (any shape), each checked.
template <typename F>
py::object map_frequencies(const py::handle& frequency_hz, F f) {
    return map_array(frequency_hz, [&](double hz) { return f(checked_frequency_hz(hz)); });
}

py::list channels() {
    py::list out;
    for (const ChannelInfo& c : kChannels) {
        py::dict d;
        d["name"] = std::string(c.name);
        d["full_name"] = std::string(c.full_name);
        d["fibre"] = std::string(c.fibre);
        d["receptor"] = std::string(c.receptor);
        d["innervation_per_cm2"] = c.innervation_per_cm2;
        d["sensation"] = std::string(c.sensation);
        d["range_hz"] = py::make_tuple(c.range_low_hz, c.range_high_hz);
        d["best_hz"] = py::make_tuple(c.best_low_hz, c.best_high_hz);
        d["shape"] = c.shape == ResponseShape::u_shape ? "U" : "flat";
        d["note"] = std::string(c.shape_note);
        out.append(d);
    }
    return out;
}

}  // namespace

void add_perception(py::module_& m) {
    using py::arg;
    const double area = kReferenceAreaCm2, duration = kReferenceDurationS;
    m.def("channels", &channels,
          "The four channels of touch (the paper's Table 1), P, NPI, NPII, NPIII, as dicts.");
    m.def(
        "threshold_db",
        [](const std::string& channel, const py::handle& frequency_hz, double contact_area_cm2,
           double duration_s) {
            const Channel c = channel_named(channel);
            const Stimulus s = stimulus(contact_area_cm2, duration_s);
            return map_frequencies(frequency_hz, [&](double f) { return threshold_db(c, f, s); });
        },
        arg("channel"), arg("frequency_hz"), arg("contact_area_cm2") = area,
        arg("duration_s") = duration,
        "Detection threshold of a channel (P, NPI, NPII, NPIII), dB re 1 um peak displacement, "
        "at each frequency; P sums over contact area (cm2) and duration (s).");
    m.def(
        "detection_threshold_db",
        [](const py::handle& frequency_hz, double contact_area_cm2, double duration_s) {
            const Stimulus s = stimulus(contact_area_cm2, duration_s);
            return map_frequencies(frequency_hz,
                                   [&](double f) { return detection_threshold_db(f, s); });
        },
        arg("frequency_hz"), arg("contact_area_cm2") = area, arg("duration_s") = duration,
        "The whole system's threshold: the lowest channel's (min rule), dB re 1 um peak.");
    m.def(
        "detecting_channel",
        [](double frequency_hz, double contact_area_cm2, double duration_s) {
            return std::string(info(detecting_channel(checked_frequency_hz(frequency_hz),
                                                      stimulus(contact_area_cm2, duration_s)))
                                   .name);
        },
        arg("frequency_hz"), arg("contact_area_cm2") = area, arg("duration_s") = duration,
        "The channel that sets the threshold at a frequency.");
    m.def(
        "sensation_level_db",
        [](const std::string& channel, const py::handle& frequency_hz, double displacement_db,
           double contact_area_cm2, double duration_s) {
            const Channel c = channel_named(channel);
            const Stimulus s = stimulus(contact_area_cm2, duration_s);
            return map_frequencies(frequency_hz, [&](double f) {
                return sensation_level_db(displacement_db, threshold_db(c, f, s));
            });
        },
        arg("channel"), arg("frequency_hz"), arg("displacement_db"), arg("contact_area_cm2") = area,
        arg("duration_s") = duration,
        "Sensation level (dB SL, 0 below threshold) of a sine of peak displacement "
        "displacement_db (dB re 1 um) on a channel, at each frequency.");
    m.def(
        "combined_sensation_db",
        [](const py::handle& levels_db) {
            const auto in =
                py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(levels_db);
            if (!in || in.ndim() < 1 || in.shape(in.ndim() - 1) != kChannels.size())
                throw py::value_error("levels_db: expected (..., 4): P, NPI, NPII, NPIII in dB SL");
            std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim() - 1);
            py::array_t<double> out(shape);
            for (py::ssize_t i = 0; i < out.size(); ++i) {
                ChannelLevels l{};
                std::copy_n(in.data() + i * 4, 4, l.begin());
                out.mutable_data()[i] = combined_sensation_db(l);
            }
            if (shape.empty()) return py::object(py::float_(out.data()[0]));
            return py::object(std::move(out));
        },
        arg("levels_db"),
        "Perceived intensity of channel sensation levels (..., 4) as one dB SL: the stronger plus "
        "half the weaker (Hollins & Roy 1996).");
}

}  // namespace tactus::python
