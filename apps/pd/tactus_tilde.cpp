// [tactus~ N -features -thru -preset NAME]: the engine as a Pure Data external, the paper's
// Max/MSP patch (Figure 4: bonk~, the analysis objects, omx.peaklim~) in one object.
//
// Inlet: the music (signal) and messages. Outlets, left to right: N actuator signals (default 1),
// with -thru the music delayed by the engine's latency (so sound and vibration stay aligned),
// with -features loudness_db, brightness_hz, noisiness and pitch_hz per analysis frame and, at
// each onset once its part is decided (parts.settle_ms after it), the message `PART STRENGTH_DB`
// (`kick -12.5`; parts kick, snare, hat, other: [route kick snare hat other] splits them).
//
// Messages are the parameter table's keys (`envelope.decay_ms 120`, `mapping.frequency.curve
// log`), `preset NAME|FILE`, `actuator [OUTLET] NAME|FILE|none`, `gain OUTLET DB`, `route OUTLET
// ROUTE` (what an outlet plays: all, kick, snare+hat, band:20-120; engine/route.hpp), `layout
// NAME|FILE` (every outlet's route, overlay, profile, trim and delay: io/layout_file.hpp),
// `trigger [FREQUENCY_HZ AMPLITUDE]`, `reset`, `print` and `save FILE`. A value goes through the
// engine's live path (Engine::set: live values glide, structural ones are swapped in with a
// crossfade); while DSP is off it is kept and the engine is prepared with it when DSP starts.
//
// Threads: Pd calls the methods and the perform routine from its one scheduler thread, never at
// once; perform() only runs the engine and copies (no allocation, lock or I/O), and the feature
// outlets are fed from a clock set in perform() (outlets must not be called from DSP).
#include <fmt/format.h>
#include <m_pd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "tactus/actuator/warnings.hpp"
#include "tactus/dsp/delay_line.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/engine/max_latency.hpp"
#include "tactus/engine/onset_decisions.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/layout_file.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/io/text_output.hpp"

static_assert(sizeof(t_sample) == sizeof(float), "tactus~ needs Pd's single-precision build");

namespace tactus::pd {
namespace {

t_class* tactus_class = nullptr;

constexpr int kMaxOutlets = Engine::kMaxActuators;

struct Options {
    int actuators = 1;
    bool features = false, thru = false;
    std::string preset;
};

// The object's state beside Pd's t_object (which must come first and stay a C struct).
class Object {
  public:
    Object(t_object* owner, const Options& options);
    ~Object();

    void dsp(t_signal** signals);
    void perform(int count) noexcept;
    void message(t_symbol* selector, int argc, t_atom* argv);
    void flush_frames();

  private:
    void set(P id, double value);
    void send_settings();
    void set_from_atom(P id, const t_atom& atom);
    void load_preset(const std::string& name);
    ActuatorProfile load_profile(const std::string& name) const;
    void load_actuator(int outlet, const std::string& name);
    void set_gain(int outlet, double gain_db);
    void set_route(int outlet, const std::string& route);
    void load_layout(const std::string& name);
    void set_outputs(std::vector<ActuatorOutput> next);
    void print() const;
    void save(const std::string& path) const;
    std::filesystem::path beside_patch(const std::string& name) const;
    void prepare(double sample_rate_hz, int block);
    void reset() noexcept;
    bool running() const { return engine_ && canvas_dspstate && !stale_; }

    t_object* owner_;
    t_canvas* canvas_;
    t_clock* clock_;
    Options options_;
    // What the engine plays, or will once prepared. The object's own state, not a mirror of the
    // engine's: there is no engine while DSP is off, and each prepare makes a new one from it
    // (Pd calls everything here on its one scheduler thread).
    Settings settings_;
    std::vector<ActuatorOutput> outputs_;
    std::unique_ptr<Engine> engine_;
    bool stale_ = true;  // settings or actuators changed while DSP was off: prepare again
    double sample_rate_hz_ = 0;
    int block_ = 0;

    // Signal vectors of the current DSP chain: the inlet, then the outlets.
    t_sample* in_ = nullptr;
    std::vector<t_sample*> out_;
    t_sample* thru_out_ = nullptr;
    DelayLine thru_;  // -thru: the input, delayed by the engine's latency as it changes

    std::vector<t_outlet*> feature_outlets_;  // loudness, brightness, noisiness, pitch, onset
    OnsetDecisions decisions_;                // an onset waits there for its part
    std::array<t_symbol*, kDrumParts> part_symbols_{};  // the onset messages' selectors
};

struct PdObject {
    t_object pd;
    t_float scalar_input;  // CLASS_MAINSIGNALIN's float
    Object* object;
};

std::string atom_text(const t_atom& atom) {
    char buffer[MAXPDSTRING];
    atom_string(&atom, buffer, sizeof buffer);
    return buffer;
}

Object::Object(t_object* owner, const Options& options)
    : owner_(owner),
      canvas_(canvas_getcurrent()),
      clock_(clock_new(
          owner, reinterpret_cast<t_method>(+[](PdObject* x) { x->object->flush_frames(); }))),
      options_(options),
      outputs_(static_cast<size_t>(options.actuators)) {
    for (int i = 0; i < options.actuators + options.thru; ++i) outlet_new(owner, &s_signal);
    if (options.features) {
        for (int i = 0; i < 4; ++i) feature_outlets_.push_back(outlet_new(owner, &s_float));
        feature_outlets_.push_back(outlet_new(owner, nullptr));  // PART STRENGTH_DB messages
        for (int i = 0; i < kDrumParts; ++i)
            part_symbols_[static_cast<size_t>(i)] =
                gensym(kDrumPartNames[static_cast<size_t>(i)].data());  // literals
    }
    if (!options.preset.empty()) load_preset(options.preset);
}

Object::~Object() {
    clock_free(clock_);
}

// Settings, actuators and the block's rate and size as they are now; the engine starts silent.
void Object::prepare(double sample_rate_hz, int block) {
    auto engine = std::make_unique<Engine>(settings_);
    engine->set_actuators(outputs_);
    if (options_.features) engine->enable_frame_queue();
    engine->prepare({.sample_rate_hz = sample_rate_hz, .max_block = block, .channels = 1});
    engine_ = std::move(engine);
    decisions_.reset();
    sample_rate_hz_ = sample_rate_hz;
    block_ = block;
    // A structural change moves the latency without a new prepare: room for the longest.
    thru_.prepare(1, max_latency_samples(sample_rate_hz), engine_->latency());
    stale_ = false;
}

// `reset`: silence from here, as after a new prepare: the engine, the -thru delay line (or the
// music heard before would come out after it) and the onsets waiting for their part.
void Object::reset() noexcept {
    if (!engine_) return;
    engine_->reset();
    thru_.reset();
    decisions_.reset();
}

void Object::dsp(t_signal** signals) {
    const double rate = signals[0]->s_sr;
    const int block = signals[0]->s_n;
    try {
        if (!engine_ || stale_ || rate != sample_rate_hz_ || block > block_) prepare(rate, block);
    } catch (const std::exception& e) {
        pd_error(owner_, "tactus~: %s", e.what());
        engine_.reset();
    }
    in_ = signals[0]->s_vec;
    out_.resize(outputs_.size());
    for (size_t i = 0; i < out_.size(); ++i) out_[i] = signals[1 + i]->s_vec;
    thru_out_ = options_.thru ? signals[1 + out_.size()]->s_vec : nullptr;
    dsp_add(
        +[](t_int* w) -> t_int* {
            // NOLINTNEXTLINE(performance-no-int-to-ptr): Pd passes dsp_add's arguments as t_int
            reinterpret_cast<Object*>(w[1])->perform(static_cast<int>(w[2]));
            return w + 3;
        },
        2, reinterpret_cast<t_int>(this), static_cast<t_int>(block));
}

void Object::perform(int count) noexcept {
    if (!engine_) {
        for (t_sample* out : out_) std::fill_n(out, count, 0.0f);
        if (thru_out_) std::fill_n(thru_out_, count, 0.0f);
        return;
    }
    // Pd may hand the inlet's vector to an outlet too: the input is copied before the engine
    // writes, and delayed by the latency the engine has after this block (a structural change
    // may have moved it), as the plugin does.
    float input[Engine::kMaxBlock];
    if (thru_out_) std::copy_n(in_, count, input);
    engine_->process(&in_, out_.data(), count);
    if (thru_out_) {
        const float* from = input;
        thru_.set_delay_samples(engine_->latency());
        thru_.process(&from, &thru_out_, count);
    }
    if (options_.features) clock_delay(clock_, 0);
}

// Feature outlets, right to left as Pd orders them, for every frame the engine produced.
void Object::flush_frames() {
    if (!engine_) return;
    const auto send_onset = [this](const DecidedOnset& onset) {
        t_atom strength;
        SETFLOAT(&strength, static_cast<t_float>(onset.strength_db));
        outlet_anything(feature_outlets_[4], part_symbols_[static_cast<size_t>(onset.part)], 1,
                        &strength);
    };
    AnalysisFrame frame;
    while (engine_->pop_frame(frame)) {
        const Features& f = frame.features;
        decisions_.add(f, send_onset);
        outlet_float(feature_outlets_[3], static_cast<t_float>(f.pitch_hz));
        outlet_float(feature_outlets_[2], static_cast<t_float>(f.noisiness));
        outlet_float(feature_outlets_[1], static_cast<t_float>(f.brightness_hz));
        outlet_float(feature_outlets_[0], static_cast<t_float>(f.loudness_db));
    }
}

void Object::set(P id, double value) {
    settings_.set(id, value);  // throws std::invalid_argument naming the key
    send_settings();
}

// The engine takes what differs from settings_ (kept for the next prepare while DSP is off).
void Object::send_settings() {
    if (!running()) {
        stale_ = true;
        return;
    }
    try {
        engine_->set(settings_);
    } catch (const std::exception&) {
        stale_ = true;  // the engine's queue is full (its DSP is not running): prepare again
    }
}

void Object::set_from_atom(P id, const t_atom& atom) {
    if (atom.a_type == A_FLOAT) return set(id, atom_getfloat(&atom));
    Settings parsed = settings_;
    parsed.set_from_text(id, atom_text(atom));  // a choice's name: "log", "on"
    set(id, parsed[id]);
}

std::filesystem::path Object::beside_patch(const std::string& name) const {
    std::filesystem::path path(name);
    if (path.is_absolute() || name.find('/') == std::string::npos) return path;
    return std::filesystem::path(canvas_getdir(canvas_)->s_name) / path;
}

// A preset replaces every setting, as --preset does: the table's defaults, then the file.
void Object::load_preset(const std::string& name) {
    Settings next;
    const std::filesystem::path file =
        name.ends_with(".toml") || name.find('/') != std::string::npos
            ? resolve_preset(beside_patch(name).string())
            : resolve_preset(name);
    apply_preset_file(next, file);
    settings_ = next;
    send_settings();
}

// A profile by name or by a file beside the patch, what the settings ask that it cannot do said
// on Pd's console.
ActuatorProfile Object::load_profile(const std::string& name) const {
    ActuatorProfile profile = tactus::load_actuator(
        resolve_actuator(name.ends_with(".toml") ? beside_patch(name).string() : name));
    for (const auto& warning : actuator_warnings(profile, settings_))
        post("tactus~: warning: %s", warning.c_str());
    return profile;
}

// A profile changes live (Engine::set_outputs: swapped in without a gap).
void Object::load_actuator(int outlet, const std::string& name) {
    std::optional<ActuatorProfile> profile;
    if (name != "none") profile = load_profile(name);
    std::vector<ActuatorOutput> next = outputs_;
    for (int i = 0; i < static_cast<int>(next.size()); ++i)
        if (outlet < 0 || i == outlet) next[static_cast<size_t>(i)].profile = profile;
    set_outputs(std::move(next));
}

// The engine's outputs: live while DSP runs, unless a delay changed (the engine's setup: it is
// prepared again, its analysis afresh).
void Object::set_outputs(std::vector<ActuatorOutput> next) {
    bool delays_changed = false;
    for (size_t k = 0; k < next.size(); ++k) {
        next[k].check(static_cast<int>(k));  // before anything changes, DSP on or off
        delays_changed |= next[k].delay_ms != outputs_[k].delay_ms;
    }
    const bool live = running() && !delays_changed;
    if (live) engine_->set_outputs(next);
    outputs_ = std::move(next);
    if (live) return;
    stale_ = true;
    if (engine_ && canvas_dspstate) prepare(sample_rate_hz_, block_);
}

void Object::set_gain(int outlet, double gain_db) {
    if (outlet < 0 || outlet >= static_cast<int>(outputs_.size()))
        throw std::invalid_argument(
            fmt::format("gain: outlet {} out of range (0 to {})", outlet, outputs_.size() - 1));
    std::vector<ActuatorOutput> next = outputs_;
    next[static_cast<size_t>(outlet)].gain_db = gain_db;
    set_outputs(std::move(next));
}

// A route changes live (a primed pipeline crossfaded in, no gap).
void Object::set_route(int outlet, const std::string& route) {
    if (outlet < 0 || outlet >= static_cast<int>(outputs_.size()))
        throw std::invalid_argument(
            fmt::format("route: outlet {} out of range (0 to {})", outlet, outputs_.size() - 1));
    std::vector<ActuatorOutput> next = outputs_;
    next[static_cast<size_t>(outlet)].route = Route::parse(route);
    set_outputs(std::move(next));
}

// Every outlet's route, overlay, profile, trim and delay, as set_outputs applies them.
void Object::load_layout(const std::string& name) {
    const Layout layout = tactus::load_layout(
        resolve_layout(name.ends_with(".toml") ? beside_patch(name).string() : name));
    if (layout.outputs.size() != outputs_.size())
        throw std::invalid_argument(fmt::format("layout {} has {} output(s), tactus~ {} outlet(s)",
                                                layout.name, layout.outputs.size(),
                                                outputs_.size()));
    std::vector<ActuatorOutput> next = layout.actuator_outputs(
        [&](const std::string& actuator) { return load_profile(actuator); });
    set_outputs(std::move(next));
}

void Object::print() const {
    post("tactus~: %d actuator outlet(s), %s", static_cast<int>(outputs_.size()),
         engine_ ? fmt::format("{:g} Hz, latency {} samples", sample_rate_hz_, engine_->latency())
                       .c_str()
                 : "not prepared (DSP off)");
    for (const ParamSpec& s : param_table())
        post("  %s %s  (%s%s)", std::string(s.key).c_str(), settings_.text_of(s.param).c_str(),
             range_text(s).c_str(), s.change == ParamChange::structural ? ", structural" : "");
}

void Object::save(const std::string& path) const {
    TextOutput output(beside_patch(path));
    output.stream() << preset_text(settings_, "saved from tactus~");
    output.commit();
    post("tactus~: saved %s", beside_patch(path).c_str());
}

void Object::message(t_symbol* selector, int argc, t_atom* argv) {
    const std::string name = selector->s_name;
    const auto symbol = [&](int i) { return i < argc ? atom_text(argv[i]) : std::string(); };
    const auto number = [&](int i) {
        if (i >= argc || argv[i].a_type != A_FLOAT)
            throw std::invalid_argument(
                fmt::format("{}: argument {} must be a number", name, i + 1));
        return static_cast<double>(atom_getfloat(&argv[i]));
    };
    try {
        if (const auto id = find_param(name)) {
            if (argc != 1)
                throw std::invalid_argument(
                    fmt::format("{}: needs one value ({})", name, range_text(spec(*id))));
            set_from_atom(*id, argv[0]);
        } else if (name == "preset" && argc == 1) {
            load_preset(symbol(0));
        } else if (name == "actuator" && (argc == 1 || argc == 2)) {
            if (argc == 2) {
                const double outlet = number(0);
                if (outlet < 0 || outlet >= static_cast<double>(outputs_.size()))
                    throw std::invalid_argument(
                        fmt::format("actuator: outlet {:g} out of range (0 to {})", outlet,
                                    outputs_.size() - 1));
                load_actuator(static_cast<int>(outlet), symbol(1));
            } else {
                load_actuator(-1, symbol(0));
            }
        } else if (name == "gain" && argc == 2) {
            set_gain(static_cast<int>(number(0)), number(1));
        } else if (name == "route" && argc == 2) {
            set_route(static_cast<int>(number(0)), symbol(1));
        } else if (name == "layout" && argc == 1) {
            load_layout(symbol(0));
        } else if (name == "trigger" && (argc == 0 || argc == 2)) {
            if (!engine_) throw std::invalid_argument("trigger: DSP is off");
            // Without arguments: a pulse at the top of the frequency mapping, full scale.
            engine_->trigger(argc ? number(0) : settings_[P::frequency_out_max],
                             argc ? number(1) : 1.0);
        } else if (name == "reset" && argc == 0) {
            reset();
        } else if (name == "print" && argc == 0) {
            print();
        } else if (name == "save" && argc == 1) {
            save(symbol(0));
        } else {
            const std::string known =
                "preset, actuator, gain, route, layout, trigger, reset, print, save";
            throw std::invalid_argument(
                fmt::format("unknown message '{}' with {} argument(s) (a parameter: did you mean "
                            "'{}'? or one of {})",
                            name, argc, nearest_param(name), known));
        }
    } catch (const std::exception& e) {
        pd_error(owner_, "tactus~: %s", e.what());
    }
}

Options parse_arguments(int argc, t_atom* argv) {
    Options options;
    for (int i = 0; i < argc; ++i) {
        const std::string arg = atom_text(argv[i]);
        if (argv[i].a_type == A_FLOAT) {
            const double n = atom_getfloat(&argv[i]);
            if (n < 1 || n > kMaxOutlets || n != std::floor(n))
                throw std::invalid_argument(
                    fmt::format("actuator outlets: {:g} (a whole number 1 to {})", n, kMaxOutlets));
            options.actuators = static_cast<int>(n);
        } else if (arg == "-features") {
            options.features = true;
        } else if (arg == "-thru") {
            options.thru = true;
        } else if (arg == "-preset" && i + 1 < argc) {
            options.preset = atom_text(argv[++i]);
        } else {
            throw std::invalid_argument(fmt::format(
                "unknown argument '{}' (N actuator outlets, -features, -thru, -preset NAME)", arg));
        }
    }
    return options;
}

void* make(t_symbol*, int argc, t_atom* argv) {
    auto* x = reinterpret_cast<PdObject*>(pd_new(tactus_class));
    x->scalar_input = 0;
    x->object = nullptr;
    try {
        x->object = new Object(&x->pd, parse_arguments(argc, argv));
    } catch (const std::exception& e) {
        pd_error(nullptr, "tactus~: %s", e.what());
        pd_free(&x->pd.ob_pd);
        return nullptr;
    }
    return x;
}

void destroy(PdObject* x) {
    delete x->object;
}

}  // namespace
}  // namespace tactus::pd

extern "C" __attribute__((visibility("default"))) void tactus_tilde_setup() {
    using namespace tactus::pd;
    tactus_class = class_new(gensym("tactus~"), reinterpret_cast<t_newmethod>(make),
                             reinterpret_cast<t_method>(destroy), sizeof(PdObject), CLASS_DEFAULT,
                             A_GIMME, A_NULL);
    CLASS_MAINSIGNALIN(tactus_class, PdObject, scalar_input);
    class_addmethod(tactus_class, reinterpret_cast<t_method>(+[](PdObject* x, t_signal** sp) {
                        if (x->object) x->object->dsp(sp);
                    }),
                    gensym("dsp"), A_CANT, A_NULL);
    class_addanything(
        tactus_class, +[](PdObject* x, t_symbol* s, int argc, t_atom* argv) {
            if (x->object) x->object->message(s, argc, argv);
        });
    class_sethelpsymbol(tactus_class, gensym("tactus~"));
    post("tactus~ %s: music to vibration (Birnbaum & Wanderley)", TACTUS_VERSION);
}
