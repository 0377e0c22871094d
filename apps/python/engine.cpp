// tactus.Engine: the library's Engine (engine/engine.hpp) for Python, as a host drives it.
// process() is the audio thread (the GIL released; one call at a time), set() and the parameter
// attributes the control thread (the live path: a change is picked up at the start of the next
// process() call, live parameters glide, structural ones are swapped in). The attributes are
// generated from the parameter table, with unit, range and help in their docstrings.
#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <mutex>
#include <optional>

#include "audio_view.hpp"
#include "parts.hpp"
#include "settings.hpp"
#include "tactus/io/analysis_rows.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/io/run_file.hpp"

namespace py = pybind11;

namespace tactus::python {
namespace {

// A parameter's value as Python shows it: a choice's name, an int, or a float.
py::object as_python(const ParamSpec& s, double value) {
    if (!s.choices.empty()) return py::str(std::string(s.choices[static_cast<size_t>(value)]));
    if (s.type == ParamType::integer) return py::int_(static_cast<long long>(value));
    return py::float_(value);
}

class PyEngine {
  public:
    // `channels`: the input's channel count, or None: the first block's (1 until then).
    PyEngine(double sample_rate_hz, const std::string& preset, const py::object& actuator_name,
             const py::object& channels, int actuators, bool keep_frames,
             const py::object& settings_dict, const py::object& layout, const py::kwargs& params)
        : channels_(channels.is_none() ? 1 : channels.cast<int>()),
          channels_given_(!channels.is_none()),
          keep_frames_(keep_frames) {
        const Settings settings = resolve_settings(preset, settings_dict, params);
        const std::vector<ActuatorOutput> outputs =
            resolve_outputs(layout, actuator_name, actuators, settings);
        actuators_ = static_cast<int>(outputs.size());
        engine_ = std::make_unique<Engine>(settings);
        engine_->set_actuators(outputs);
        if (keep_frames_) engine_->enable_frame_queue();
        prepare(sample_rate_hz, channels_);
    }

    py::array_t<float> process(const py::handle& block) {
        const AudioView in = audio_view(block);
        const std::unique_lock running(processing_, std::try_to_lock);
        if (!running.owns_lock())
            throw py::value_error("process(): already running in another thread");
        take_channels(in.channels, "block");
        processed_ = processed_ || in.frames > 0;
        AudioOutput out = audio_output(in.frames, actuators_);
        if (in.frames == 0) return out.array;
        BufferSource source(in.pointers, in.frames, engine_->sample_rate_hz(), "block");
        int64_t done = 0;
        run(source, RunTail::none, [&](const float* const* vibration, int count) {
            for (size_t c = 0; c < out.pointers.size(); ++c)
                std::copy_n(vibration[c], count, out.pointers[c] + done);
            done += count;
        });
        return out.array;
    }

    // Every frame of `source` (its tail too with ring_out), as process() runs a block: the
    // run loop of the command line (io/run_file.hpp). Returns float32 (frames, actuators).
    py::array_t<float> stream(AudioSource& source, bool ring_out) {
        const std::unique_lock running(processing_, std::try_to_lock);
        if (!running.owns_lock())
            throw py::value_error("stream: the engine is running in another thread");
        take_channels(source.channels(), source.name());
        processed_ = true;
        std::vector<std::vector<float>> vibration(static_cast<size_t>(actuators_));
        run(source, ring_out ? RunTail::ring_out : RunTail::none,
            [&](const float* const* v, int count) {
                for (size_t c = 0; c < vibration.size(); ++c)
                    vibration[c].insert(vibration[c].end(), v[c], v[c] + count);
            });
        AudioOutput out = audio_output(static_cast<int>(vibration[0].size()), actuators_);
        for (size_t c = 0; c < vibration.size(); ++c)
            std::copy(vibration[c].begin(), vibration[c].end(), out.pointers[c]);
        return out.array;
    }

    // The frames analysed since the last call: the first columns of tactus.analyze().
    py::dict frames() {
        if (!keep_frames_) throw py::value_error("frames(): make the engine with keep_frames=True");
        const auto running = wait_for_process();
        const double rate = engine_->sample_rate_hz();
        constexpr size_t kColumns = AnalysisRows::kFrameColumns;
        py::dict out;
        std::vector<py::array_t<double>> columns;
        for (size_t c = 0; c < kColumns; ++c) {
            columns.emplace_back(static_cast<py::ssize_t>(frames_.size()));
            out[py::str(std::string(AnalysisRows::kColumns[c]))] = columns.back();
        }
        for (size_t r = 0; r < frames_.size(); ++r) {
            const AnalysisRows::Row row = AnalysisRows::row_of(frames_[r], rate);
            for (size_t k = 0; k < kColumns; ++k) columns[k].mutable_data()[r] = row[k];
        }
        frames_.clear();
        out["part"] = part_names(out["part"]);
        return out;
    }

    void set(const std::string& name, const py::handle& value) {
        set_param(param_named(name), value);
    }

    void set_param(P id, const py::handle& value) {
        try {
            engine_->set(id, param_value(id, value));
        } catch (const std::invalid_argument& e) {
            throw py::value_error(e.what());
        }
    }

    py::object get(P id) const { return as_python(spec(id), engine_->settings()[id]); }

    // One snapshot for every key: a whole set of settings even while another thread sets.
    py::dict settings() const {
        const Settings now = engine_->settings();
        py::dict out;
        for (const ParamSpec& s : param_table())
            out[py::str(std::string(s.key))] = as_python(s, now[s.param]);
        return out;
    }

    void reset() {
        const auto running = wait_for_process();
        engine_->reset();
        frames_.clear();
    }

    const Engine& engine() const { return *engine_; }
    int channels() const { return channels_; }
    int actuators() const { return actuators_; }

  private:
    // Made without a channel count, the engine takes the first input's: nothing has been
    // processed, so preparing it again (settings as set, pending changes folded in) loses
    // nothing.
    void take_channels(int channels, const std::string& what) {
        if (channels != channels_ && !channels_given_ && !processed_)
            prepare(engine_->sample_rate_hz(), channels);
        if (channels != channels_)
            throw py::value_error(fmt::format(
                "{}: {} channel(s), the engine was made for {} ({}); make another with "
                "Engine(rate, channels={})",
                what, channels, channels_,
                channels_given_ ? fmt::format("channels={}", channels_) : "its first block's",
                channels));
    }

    // The run loop over `source` with the GIL released, frames taken off the engine's queue
    // between blocks, as a live front end does; its errors as ValueError.
    void run(AudioSource& source, RunTail tail,
             const std::function<void(const float* const*, int)>& on_output) {
        const auto take = [&](const float* const* vibration, int count) {
            on_output(vibration, count);
            if (keep_frames_)
                for (AnalysisFrame f; engine_->pop_frame(f);) frames_.push_back(f);
        };
        try {
            const py::gil_scoped_release unlocked;
            run_source(source, *engine_, {.on_output = take}, tail, RunPrepare::none);
        } catch (const std::runtime_error& e) {
            throw py::value_error(e.what());
        }
    }

    void prepare(double sample_rate_hz, int channels) {
        try {
            engine_->prepare({.sample_rate_hz = sample_rate_hz,
                              .max_block = kStreamBlockFrames,
                              .channels = channels});
        } catch (const std::invalid_argument& e) {
            throw py::value_error(e.what());
        }
        channels_ = channels;
    }

    // Waits for a process() running in another thread, without the GIL (which that thread takes
    // back before it lets go of the engine).
    std::unique_lock<std::mutex> wait_for_process() {
        std::unique_lock running(processing_, std::defer_lock);
        const py::gil_scoped_release unlocked;
        running.lock();
        return running;
    }

    std::unique_ptr<Engine> engine_;
    int channels_;
    bool channels_given_;
    int actuators_;
    bool keep_frames_;
    bool processed_ = false;  // a block with frames went through: the channel count is fixed
    std::mutex processing_;   // one process() at a time: it is the engine's audio thread
    std::vector<AnalysisFrame> frames_;
};

std::string param_doc(const ParamSpec& s) {
    std::string doc = fmt::format("{} ({}, {}, default {}): {}.", s.key, range_text(s),
                                  s.change == ParamChange::live ? "live" : "structural",
                                  Settings().text_of(s.param), s.help);
    if (!s.choices.empty()) {
        std::string names;
        for (auto c : s.choices) names.append(names.empty() ? "" : ", ").append(c);
        doc += fmt::format(" Choices: {}.", names);
    }
    if (s.change == ParamChange::live && s.smoothing_ms > 0)
        doc += fmt::format(" Glides over {:g} ms.", s.smoothing_ms);
    return doc;
}

}  // namespace

void add_engine(py::module_& m) {
    using py::arg;
    py::class_<PyEngine> engine(m, "Engine",
                                R"(The tactus engine, block by block, as a host runs it.

Engine(sample_rate, preset="music", actuator=None, channels=None, actuators=1,
       keep_frames=False, settings=None, layout=None, **params)

layout: a layout's name or .toml path (tactus.layouts folder; --layout): one output per layout
output, each playing its route (all, kick, band:20-120, channel:1, ...) through its actuator, in
the layout's order; then actuator and actuators are left out.

channels: the input's channel count; None takes the first block's (a stereo file from
tactus.read gives 2); every later block must have as many.

process(block) takes any number of frames, (frames,) or (frames, channels), and returns the
vibration, float32 (frames, actuators); blocks of any sizes give the output of one call.
set(key, value) and the parameter attributes change a parameter through the live path: it
applies from the next process() call (live parameters glide over their smoothing time,
structural ones build a new pipeline and crossfade to it). Every parameter of the table is an
attribute named by its key with dots as underscores (engine.envelope_decay_ms).)");
    engine
        .def(py::init<double, const std::string&, const py::object&, const py::object&, int, bool,
                      const py::object&, const py::object&, const py::kwargs&>(),
             arg("sample_rate"), arg("preset") = kDefaultPreset, arg("actuator") = py::none(),
             arg("channels") = py::none(), arg("actuators") = 1, arg("keep_frames") = false,
             arg("settings") = py::none(), arg("layout") = py::none())
        .def("process", &PyEngine::process, arg("block"),
             "The vibration for the next block: float32 (frames, actuators).")
        .def("set", &PyEngine::set, arg("key"), arg("value"),
             "Sets a parameter (key or Python name; a number, or a choice's name) from the next "
             "block on. ValueError naming the key for an unknown key or a value out of range.")
        .def("frames", &PyEngine::frames,
             "The analysis frames since the last call (keep_frames=True): a dict of float64 "
             "arrays, the first 19 columns of tactus.analyze().")
        .def("reset", &PyEngine::reset, "Back to silence, as if nothing had been processed.")
        .def_property_readonly(
            "latency", [](const PyEngine& e) { return e.engine().latency(); },
            "Samples the vibration lags the input (the limiter's look-ahead).")
        .def_property_readonly(
            "hop_samples", [](const PyEngine& e) { return e.engine().hop_samples(); },
            "Input samples between analysis frames, on average (the analysis hop is whole samples "
            "at the 16 kHz analysis rate; frames end at whole input samples).")
        .def_property_readonly(
            "sample_rate", [](const PyEngine& e) { return e.engine().sample_rate_hz(); }, "Hz.")
        .def_property_readonly("channels", &PyEngine::channels,
                               "Input channels (made with channels=None: 1 until the first "
                               "block, then that block's).")
        .def_property_readonly("actuators", &PyEngine::actuators, "Actuator outputs.")
        .def_property_readonly("settings", &PyEngine::settings,
                               "Every parameter as last set: {key: value}.");
    m.def(
        "stream_file",
        [](PyEngine& engine, const std::filesystem::path& path, bool ring_out) {
            std::optional<FileSource> source;
            try {
                source.emplace(path, kStreamBlockFrames);
            } catch (const std::runtime_error& e) {
                throw py::value_error(e.what());
            }
            return engine.stream(*source, ring_out);
        },
        arg("engine"), arg("path"), arg("ring_out") = false,
        R"(The engine run over an audio file, block by block as `tactus render` reads it: the
vibration, float32 (frames, actuators), as process() on the file's samples returns it. The file
must have the engine's sample rate (and its channel count, as process()). ring_out: silence fed
after the file until the vibration has died away, as `tactus render` does.)");
    m.def(
        "stream_buffer",
        [](PyEngine& engine, const py::handle& x, bool ring_out) {
            const AudioView in = audio_view(x);
            if (in.frames == 0) throw py::value_error("audio: no audio frames");
            BufferSource source(in.pointers, in.frames, engine.engine().sample_rate_hz(), "audio");
            return engine.stream(source, ring_out);
        },
        arg("engine"), arg("x"), arg("ring_out") = false,
        R"(stream_file() on audio in memory, (frames,) or (frames, channels) at the engine's
sample rate: the same loop, the same output.)");
    for (const ParamSpec& s : param_table()) {
        const P id = s.param;
        engine.def_property(
            identifier_of(s).c_str(), [id](const PyEngine& e) { return e.get(id); },
            [id](PyEngine& e, const py::handle& value) { e.set_param(id, value); },
            param_doc(s).c_str());
    }
}

}  // namespace tactus::python
