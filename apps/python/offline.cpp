// tactus.render, analyze, onsets, meter, read and write: the command line's offline commands on
// numpy arrays, driving the library as the commands do (apps/tactus/render.cpp, analyze.cpp,
// onsets.cpp, meter.cpp) so their values are the commands' values, bit for bit. The GIL is
// released while audio is processed.
#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <limits>
#include <optional>

#include "audio_view.hpp"
#include "parts.hpp"
#include "settings.hpp"
#include "tactus/engine/onset_decisions.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/analysis_rows.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/audio_writer.hpp"
#include "tactus/io/meter_run.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/io/run_file.hpp"
#include "tactus/perception/meter.hpp"

namespace py = pybind11;

namespace tactus::python {
namespace {

constexpr int kBlock = kStreamBlockFrames;  // the command line's blocks

ProcessSpec spec_for(double sample_rate_hz, const AudioView& in) {
    if (in.frames == 0) throw py::value_error("audio: no audio frames");
    try {
        Engine::check_sample_rate(sample_rate_hz);
    } catch (const std::invalid_argument& e) {
        throw py::value_error(e.what());
    }
    return {.sample_rate_hz = sample_rate_hz, .max_block = kBlock, .channels = in.channels};
}

// The audio as the library's run loop reads it (io/audio_source.hpp): the command line's loop,
// on samples in memory.
BufferSource source_of(const AudioView& in, double sample_rate_hz) {
    return BufferSource(in.pointers, in.frames, sample_rate_hz, "audio");
}

// Runs `run` with the GIL released, a run loop's error as a ValueError.
template <typename Run>
void unlocked(const Run& run) {
    try {
        const py::gil_scoped_release released;
        run();
    } catch (const std::runtime_error& e) {
        throw py::value_error(e.what());
    }
}

void prepare(Engine& engine, const ProcessSpec& spec) {
    try {
        engine.prepare(spec);
    } catch (const std::invalid_argument& e) {
        throw py::value_error(e.what());
    }
}

// Columns of equal length as a dict of float64 arrays, in `names`' order.
template <typename Names, typename Row>
py::dict columns(const Names& names, const std::vector<Row>& rows) {
    py::dict out;
    for (size_t c = 0; c < std::size(names); ++c) {
        py::array_t<double> column(static_cast<py::ssize_t>(rows.size()));
        double* data = column.mutable_data();
        for (size_t r = 0; r < rows.size(); ++r) data[r] = rows[r][c];
        out[py::str(std::string(names[c]))] = column;
    }
    return out;
}

py::object render(const py::handle& x, double sample_rate_hz, const std::string& preset,
                  const py::object& actuator_name, int actuators, const py::object& settings_dict,
                  const py::object& layout, const py::kwargs& params) {
    const Settings settings = resolve_settings(preset, settings_dict, params);
    const std::vector<ActuatorOutput> outputs =
        resolve_outputs(layout, actuator_name, actuators, settings);
    actuators = static_cast<int>(outputs.size());
    const AudioView in = audio_view(x);
    const ProcessSpec spec = spec_for(sample_rate_hz, in);
    Engine engine(settings);
    engine.set_actuators(outputs);
    prepare(engine, spec);
    // As `tactus render`, the vibration rings out after the input: its tail (at most
    // kMaxTailS) follows it in the same array, returned as long as it came out; the analysis
    // runs ahead on a thread of its own.
    const auto most =
        static_cast<int>(in.frames + std::ceil(kMaxTailS * sample_rate_hz) + Engine::kMaxBlock);
    AudioOutput out = audio_output(most, actuators);
    int64_t frames = 0;
    BufferSource source = source_of(in, sample_rate_hz);
    const auto on_output = [&](const float* const* vibration, int count) {
        for (size_t c = 0; c < out.pointers.size(); ++c)
            std::copy_n(vibration[c], count, out.pointers[c] + frames);
        frames += count;
    };
    unlocked([&] {
        run_source(source, engine, {.on_output = on_output}, RunTail::ring_out, RunPrepare::none,
                   RunAnalysis::ahead);
    });
    return out.array[py::slice(0, static_cast<py::ssize_t>(frames), 1)];
}

py::dict analyze(const py::handle& x, double sample_rate_hz, const std::string& preset,
                 const py::object& actuator_name, const py::object& settings_dict,
                 const py::kwargs& params) {
    const Settings settings = resolve_settings(preset, settings_dict, params);
    const auto actuator = resolve_actuator_for(actuator_name, settings);
    ActuatorProfile metered;
    try {
        metered = actuator ? *actuator : load_actuator(resolve_actuator(kDefaultActuator));
    } catch (const std::exception& e) {
        throw py::value_error(e.what());
    }
    const AudioView in = audio_view(x);
    const ProcessSpec spec = spec_for(sample_rate_hz, in);
    Engine engine(settings);
    engine.set_actuator(actuator);
    std::vector<AnalysisRows::Row> rows;
    AnalysisRows table(engine, metered, [&](const AnalysisRows::Row& row) { rows.push_back(row); });
    engine.enable_frame_queue();
    prepare(engine, spec);
    BufferSource source = source_of(in, sample_rate_hz);
    unlocked([&] {  // as `tactus analyze`
        table.start(sample_rate_hz);
        run_source(source, engine,
                   {.on_output =
                        [&](const float* const* v, int n) {
                            table.take_frames(engine);
                            table.vibration(v[0], n);
                        }},
                   RunTail::none, RunPrepare::none);
        table.finish();
    });
    py::dict out = columns(AnalysisRows::kColumns, rows);
    out["part"] = part_names(out["part"]);
    return out;
}

py::dict onsets(const py::handle& x, double sample_rate_hz, const std::string& preset,
                const py::object& settings_dict, const py::kwargs& params) {
    const Settings settings = resolve_settings(preset, settings_dict, params);
    const AudioView in = audio_view(x);
    const ProcessSpec spec = spec_for(sample_rate_hz, in);
    Analyzer analyzer;
    std::vector<std::array<double, 4>> rows;  // the part as its index
    OnsetDecisions decisions;
    const auto add = [&](const DecidedOnset& o) {
        rows.push_back({static_cast<double>(o.onset_sample) / sample_rate_hz,
                        static_cast<double>(o.decided_sample) / sample_rate_hz, o.strength_db,
                        static_cast<double>(o.part)});
    };
    BufferSource source = source_of(in, spec.sample_rate_hz);
    unlocked([&] {  // as `tactus onsets`
        analyse_source(source, analyzer, settings, OnsetDecisions::reads(),
                       [&](const Features& f) { decisions.add(f, add); });
        decisions.finish(add);
    });
    constexpr std::array<std::string_view, 4> kNames = {"onset_s", "decided_s", "strength_db",
                                                        "part"};
    py::dict out = columns(kNames, rows);
    out["part"] = part_names(out["part"]);
    return out;
}

py::dict meter(const py::handle& vibration, double sample_rate_hz, const std::string& actuator_name,
               double contact_area_cm2) {
    ActuatorProfile actuator;
    try {
        actuator = load_actuator(resolve_actuator(actuator_name));
        Settings().set(P::perception_contact_area_cm2, contact_area_cm2);  // its range
    } catch (const std::exception& e) {
        throw py::value_error(e.what());
    }
    const AudioView in = audio_view(vibration);
    const ProcessSpec spec = spec_for(sample_rate_hz, in);
    std::vector<std::array<double, 6>> rows;
    BufferSource source = source_of(in, spec.sample_rate_hz);
    unlocked([&] {  // as `tactus meter`
        meter_source(source, actuator, contact_area_cm2, [&](const perception::MeterReading& r) {
            rows.push_back({r.time_s, r.level_db[0], r.level_db[1], r.level_db[2], r.level_db[3],
                            r.combined_db});
        });
    });
    std::vector<std::string> names = {"time_s"};
    for (const auto& c : perception::kChannels) names.push_back(std::string(c.name) + "_sl_db");
    names.push_back("combined_sl_db");
    return columns(names, rows);
}

// Decodes into `out`'s channels (allocated for the header's length): false if the file holds more
// frames than its header says (some compressed formats only estimate it).
bool read_into(AudioReader& reader, AudioOutput& out, int& frames) {
    const int channels = reader.channels(), expected = frames;
    std::vector<float*> at(static_cast<size_t>(channels));
    for (frames = 0; frames < expected;) {
        for (int c = 0; c < channels; ++c) at[c] = out.pointers[c] + frames;
        const int got = reader.read(at.data(), std::min(kBlock, expected - frames));
        if (got == 0) return true;
        frames += got;
    }
    ChannelBlock beyond(channels, 1);
    return reader.read(beyond.data(), 1) == 0;
}

// A file whose header does not say its length, or says too little: decoded into growing buffers,
// then copied once.
py::tuple read_growing(const std::filesystem::path& path) {
    std::vector<std::vector<float>> channels;
    double sample_rate_hz = 0;
    {
        const py::gil_scoped_release unlocked;
        AudioReader reader(path);
        sample_rate_hz = reader.sample_rate_hz();
        ChannelBlock block(reader.channels(), kBlock);
        channels.resize(static_cast<size_t>(reader.channels()));
        while (const int got = reader.read(block.data(), kBlock))
            for (int c = 0; c < reader.channels(); ++c)
                channels[c].insert(channels[c].end(), block[c], block[c] + got);
    }
    if (channels[0].empty())
        throw std::runtime_error(fmt::format("{}: no audio frames", path.string()));
    if (channels[0].size() > static_cast<size_t>(std::numeric_limits<int>::max()))
        throw std::runtime_error(fmt::format("{}: more than 2^31 frames", path.string()));
    AudioOutput out =
        audio_output(static_cast<int>(channels[0].size()), static_cast<int>(channels.size()));
    for (size_t c = 0; c < channels.size(); ++c)
        std::copy(channels[c].begin(), channels[c].end(), out.pointers[c]);
    return py::make_tuple(out.array, sample_rate_hz);
}

py::tuple read(const std::filesystem::path& path) {
    try {
        std::optional<AudioOutput> out;
        int frames = 0;
        double sample_rate_hz = 0;
        {
            AudioReader reader(path);
            sample_rate_hz = reader.sample_rate_hz();
            if (reader.frames() <= 0 || reader.frames() > std::numeric_limits<int>::max())
                return read_growing(path);
            frames = static_cast<int>(reader.frames());
            out.emplace(audio_output(frames, reader.channels()));
            bool complete = false;
            {
                const py::gil_scoped_release unlocked;
                complete = read_into(reader, *out, frames);
            }
            if (!complete) return read_growing(path);
        }
        if (frames == 0)
            throw std::runtime_error(fmt::format("{}: no audio frames", path.string()));
        if (frames < out->array.shape(0))  // a header that promised more (a view of what came)
            return py::make_tuple(out->array[py::slice(0, frames, 1)], sample_rate_hz);
        return py::make_tuple(out->array, sample_rate_hz);
    } catch (const std::runtime_error& e) {
        throw py::value_error(e.what());
    }
}

void write(const std::filesystem::path& path, const py::handle& x, double sample_rate_hz) {
    const AudioView in = audio_view(x);
    try {
        const py::gil_scoped_release unlocked;
        AudioWriter writer(path, sample_rate_hz, in.channels);
        std::vector<const float*> block(in.pointers.size());
        for (int done = 0; done < in.frames; done += kBlock) {
            for (size_t c = 0; c < block.size(); ++c) block[c] = in.pointers[c] + done;
            writer.write(block.data(), std::min(kBlock, in.frames - done));
        }
        writer.commit();
    } catch (const std::exception& e) {
        throw py::value_error(e.what());
    }
}

}  // namespace

void add_offline(py::module_& m) {
    using py::arg;
    m.def("render", &render, arg("x"), arg("sample_rate"), arg("preset") = kDefaultPreset,
          arg("actuator") = py::none(), arg("actuators") = 1, arg("settings") = py::none(),
          arg("layout") = py::none(),
          R"(The vibration for audio x, as `tactus render` writes it (bit for bit).

x: float array, (frames,) or (frames, channels), full scale 1 (any channel count: analysed as
   their mean, their loudness summed as ITU-R BS.1770 sums it).
sample_rate: Hz, 8000 to 192000.
preset: a preset name (tactus.presets()) or a .toml path (--preset).
actuator: None, an actuator profile name or a .toml path (--actuator); what the settings ask that
   it cannot do is reported as warnings.
actuators: identical actuator channels (--channels).
layout: a layout's name or .toml path (--layout): one output per layout output, each its route
   through its actuator, in the layout's order (the vibration only: no sound channels); then
   actuator and actuators are left out.
settings: {"envelope.decay_ms": 120, ...}, and/or keyword arguments by Python name
   (envelope_decay_ms=120): --set. Choices take their names ("log", "on").
Returns float32 (frames, actuators). Raises ValueError with the command line's messages.)");
    m.def("analyze", &analyze, arg("x"), arg("sample_rate"), arg("preset") = kDefaultPreset,
          arg("actuator") = py::none(), arg("settings") = py::none(),
          R"(Every analysis frame's features, vibration program and sensation levels, the
columns of `tactus analyze` (the same values), as a dict of float64 arrays: time_s, loudness_db,
brightness_hz, noisiness, pitch_hz, pitch_confidence, onset_odf, onset, onset_time_s, hit_db,
hit_brightness_hz, part (the latest hit's drum part: an array of names, tactus.drum_parts),
part_decided, hit_strength_db, frequency_hz, amplitude, square_mix, trigger, attack_ms, decay_ms, sustain, flutter_hz,
flutter_amplitude, pressure, P_sl_db, NPI_sl_db, NPII_sl_db, NPIII_sl_db, combined_sl_db.
The sensation levels are metered through `actuator` (default: voice-coil). Arguments as render().)");
    m.def("onsets", &onsets, arg("x"), arg("sample_rate"), arg("preset") = kDefaultPreset,
          arg("settings") = py::none(),
          R"(The onsets `tactus onsets` prints (the ones render() triggers pulses on), as a dict
of arrays: onset_s (estimated start), decided_s (when it was decided), strength_db (what the hit
added above what was sounding) and part (its drum part's name, tactus.drum_parts), both read
parts.settle_ms after the onset.)");
    m.attr("drum_parts") = drum_part_names();
    m.def("meter", &meter, arg("vibration"), arg("sample_rate"), arg("actuator") = "voice-coil",
          arg("contact_area_cm2") = Settings()[P::perception_contact_area_cm2],
          R"(The sensation-level meter over time, as `tactus meter -o` writes it: a dict of
float64 arrays time_s, P_sl_db, NPI_sl_db, NPII_sl_db, NPIII_sl_db, combined_sl_db (dB SL every
10 ms; 0: not engaged). vibration: (frames,) or (frames, actuators), metered as their mean
through the actuator profile at the contact area (cm2).)");
    m.def("read", &read, arg("path"),
          R"(An audio file as the command line reads it (libsndfile): (float32 array
(frames, channels), sample rate).)");
    m.def("write", &write, arg("path"), arg("x"), arg("sample_rate"),
          R"(A float WAV as `tactus render` writes it: to a temporary file beside `path`,
renamed over it only when complete.)");
}

}  // namespace tactus::python
