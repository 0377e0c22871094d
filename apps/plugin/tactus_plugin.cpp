// The tactus plugin (DPF: LV2, VST3, CLAP and the JACK standalone from this one source): music
// in, the engine's vibration out on every actuator channel, the music passed through delayed by
// the engine's latency, which is reported to the host.
//
// Threads. The host's audio thread calls run() and, often, setParameterValue(); neither
// allocates, locks or makes a system call: a parameter goes into HostParameters' atomics and
// the ControlThread hands it to Engine::set (a live parameter glides, a structural one is
// built there and crossfaded in by the engine); a program (a preset read at construction)
// is stored the same way. The host's main thread calls activate(), setState() and getState();
// engine_mutex_ keeps it and the control thread off the engine's setup at the same time. The
// audio thread never takes that mutex.
//
// Parameters come from the one table (plugin_params.hpp: index = stable id, 0 = bypass), the
// state is the engine's TOML (plugin_state.hpp), the programs are presets/*.toml.
//
// Layout. A second state, a file path the host may set (LV2: patch:writable, set through the
// worker; every format: saved and restored with the session), names a layout (io/layout_file.hpp):
// Vibration 1, 2 play its outputs in order, each its route, overlay, profile, trim and delay;
// ports past its outputs fade to silence. Routes, overlays, profiles and trims change live
// (Engine::set_outputs, no gap); a changed delay waits for the next activation.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "DistrhoPlugin.hpp"
#include "bypass_ramp.hpp"
#include "control_thread.hpp"
#include "factory_presets.hpp"
#include "host_parameters.hpp"
#include "plugin_params.hpp"
#include "plugin_state.hpp"
#include "tactus/actuator/warnings.hpp"
#include "tactus/core/units.hpp"
#include "tactus/dsp/delay_line.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/engine/max_latency.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/layout_file.hpp"
#include "tactus/io/preset.hpp"

START_NAMESPACE_DISTRHO

namespace tp = tactus::plugin;

class TactusPlugin : public Plugin {
  public:
    static constexpr int kInputs = DISTRHO_PLUGIN_NUM_INPUTS;
    static constexpr int kActuators = DISTRHO_PLUGIN_NUM_OUTPUTS - DISTRHO_PLUGIN_NUM_INPUTS;

    TactusPlugin()
        : Plugin(tp::parameter_count(), static_cast<uint32_t>(std::size(tp::kFactoryPresets)),
                 kStates),
          rows_(tp::parameter_count()) {
        for (uint32_t index = 0; index < rows_.size(); ++index) rows_[index] = tp::param_at(index);
        // Presets read here, once: a host may select one from its audio thread. The one that
        // is the table's defaults comes first (program 0, which some hosts load at start).
        for (const tp::FactoryPreset& preset : tp::kFactoryPresets) {
            Program& program = programs_.emplace_back(Program{preset.name, {}});
            try {
                tactus::apply_preset_text(program.settings, preset.text, preset.name);
            } catch (const std::exception& e) {
                d_stderr2("tactus: %s", e.what());
                program.settings = tactus::Settings{};
            }
        }
        std::stable_partition(programs_.begin(), programs_.end(),
                              [](const Program& p) { return p.settings == tactus::Settings{}; });
        engine_.set_actuators(outputs_);
        if (!isDummyInstance())
            control_ = std::make_unique<tp::ControlThread>([this] { return take_changes(); });
    }
    ~TactusPlugin() override { control_.reset(); }  // before the engine it drives

  protected:
    // ---- description ----
    const char* getLabel() const override { return "tactus"; }
    const char* getDescription() const override {
        return "Music to vibrotactile feedback: analysis, mapping, synthesis and "
               "post-processing for vibration actuators (Birnbaum & Wanderley)";
    }
    const char* getMaker() const override { return "tactus"; }
    const char* getHomePage() const override { return "urn:tactus"; }
    const char* getLicense() const override { return "GPL-3.0-or-later"; }
    uint32_t getVersion() const override { return d_version(0, 1, 0); }
    int64_t getUniqueId() const override { return d_cconst('t', 'c', 't', 's'); }

    void initAudioPort(bool input, uint32_t index, AudioPort& port) override {
        if (input) {
            port.groupId = kPortGroupStereo;
            port.name = index == 0 ? "Music L" : "Music R";
            port.symbol = index == 0 ? "music_l" : "music_r";
        } else if (index < kActuators) {
            port.groupId = kVibrationGroup;
            port.name = String(fmt::format("Vibration {}", index + 1).c_str());
            port.symbol = String(fmt::format("vibration_{}", index + 1).c_str());
        } else {
            port.groupId = kPortGroupStereo;
            port.name = index == kActuators ? "Music L (delayed)" : "Music R (delayed)";
            port.symbol = index == kActuators ? "music_out_l" : "music_out_r";
        }
    }
    void initPortGroup(uint32_t groupId, PortGroup& group) override {
        if (groupId != kVibrationGroup) return Plugin::initPortGroup(groupId, group);
        group.name = "Vibration";
        group.symbol = "vibration";
    }

    void initParameter(uint32_t index, Parameter& parameter) override {
        if (index == tp::kBypassIndex)
            return parameter.initDesignation(kParameterDesignationBypass);
        const std::optional<tactus::P> row = rows_[index];
        if (!row) {  // a retired id: kept so that no later id moves
            parameter.name = parameter.symbol = String(fmt::format("retired_{}", index).c_str());
            parameter.hints = 0;
            return;
        }
        const tactus::ParamSpec& s = tactus::spec(*row);
        using tactus::ParamType;
        parameter.hints = kParameterIsAutomatable;
        if (s.type != ParamType::real) parameter.hints |= kParameterIsInteger;
        if (s.type == ParamType::toggle) parameter.hints |= kParameterIsBoolean;
        if (s.curve == tactus::ParamCurve::log && s.min > 0)
            parameter.hints |= kParameterIsLogarithmic;
        parameter.name = String(std::string(s.key).c_str());
        parameter.symbol = String(tactus::identifier_of(s).c_str());
        parameter.unit = String(std::string(s.unit).c_str());
        parameter.description = String(std::string(s.help).c_str());
        parameter.ranges = ParameterRanges(static_cast<float>(s.default_value),
                                           static_cast<float>(s.min), static_cast<float>(s.max));
        if (s.type == ParamType::choice && !s.choices.empty()) {
            const auto count = static_cast<uint32_t>(s.choices.size());
            auto* values = new ParameterEnumerationValue[count];
            for (uint32_t i = 0; i < count; ++i)
                values[i] = ParameterEnumerationValue(static_cast<float>(i),
                                                      std::string(s.choices[i]).c_str());
            parameter.enumValues.count = count;
            parameter.enumValues.restrictedMode = true;
            parameter.enumValues.values = values;  // DPF deletes it
        }
    }

    void initProgramName(uint32_t index, String& name) override {
        name = String(std::string(programs_[index].name).c_str());
    }
    void initState(uint32_t index, State& state) override {
        if (index == kLayoutState) {
            state.key = kLayoutKey;
            state.label = "Layout";
            state.description =
                "the actuator outputs (a layout .toml file): Vibration 1, 2 play its outputs in "
                "order, each its route, actuator, trim and delay; none: both play everything";
            state.defaultValue = "";
            state.hints = kStateIsFilenamePath | kStateIsOnlyForDSP;
            return;
        }
        state.key = tp::kStateKey;
        state.label = "tactus settings (preset TOML)";
        state.defaultValue = String(tp::state_text(tactus::Settings{}).c_str());
        state.hints = kStateIsOnlyForDSP;
    }

    // ---- parameters: any thread, the audio thread included ----
    float getParameterValue(uint32_t index) const override {
        if (index == tp::kBypassIndex) return bypassed_.load() ? 1.0f : 0.0f;
        const std::optional<tactus::P> row = index < rows_.size() ? rows_[index] : std::nullopt;
        return row ? static_cast<float>(host_.value(*row)) : 0.0f;
    }
    void setParameterValue(uint32_t index, float value) override {
        if (index == tp::kBypassIndex) return bypassed_.store(value > 0.5f);
        if (index < rows_.size())
            if (const std::optional<tactus::P> row = rows_[index]) host_.set_from_host(*row, value);
    }

    // Any thread, atomics only: the control thread takes it at its next poll. (LV2 hosts load
    // the programs as presets, lv2_entry.cpp: DPF's LV2 select_program would build the state.)
    void loadProgram(uint32_t index) override {
        if (index < programs_.size()) host_.set_all(programs_[index].settings);
    }

    // ---- main thread ----
    String getState(const char* key) const override {
        if (std::string_view(key) == kLayoutKey) {
            const std::lock_guard lock(engine_mutex_);
            return String(layout_path_.c_str());
        }
        if (std::string_view(key) != tp::kStateKey) return String();
        return String(tp::state_text(host_.settings()).c_str());
    }
    // Main thread, or LV2's worker thread for a layout the host sets while audio runs.
    void setState(const char* key, const char* value) override {
        if (std::string_view(key) == kLayoutKey) return load_layout(value);
        if (std::string_view(key) != tp::kStateKey) return;
        const tp::RestoredState restored = tp::restore_state(value);
        if (!restored.error.empty())
            d_stderr2("tactus: state not restored, defaults instead: %s", restored.error.c_str());
        host_.set_all(restored.settings);
        if (control_) control_->wake();  // never the audio thread: taken now, not at the poll
    }

    void activate() override {
        const std::lock_guard lock(engine_mutex_);
        engine_.set_actuators(outputs_);  // a delay changed while active takes effect here
        apply_changes();
        const int block =
            std::clamp(static_cast<int>(getBufferSize()), 1, tactus::Engine::kMaxBlock);
        try {
            engine_.prepare(
                {.sample_rate_hz = getSampleRate(), .max_block = block, .channels = kInputs});
        } catch (const std::exception& e) {  // a sample rate the engine does not run at
            d_stderr2("tactus: %s", e.what());
            prepared_ = false;
            return;
        }
        input_.assign(kInputs, std::vector<float>(static_cast<size_t>(block)));
        block_ = block;
        delay_.prepare(kInputs, tactus::max_latency_samples(getSampleRate()), engine_.latency());
        ramp_.prepare(getSampleRate());
        ramp_.reset(bypassed_.load());
        for (size_t k = 0; k < unused_.size(); ++k) {
            unused_[k].prepare(getSampleRate());
            unused_[k].reset(static_cast<int>(k) >= playing_.load());
        }
        latency_samples_ = engine_.latency();
        setLatency(static_cast<uint32_t>(latency_samples_));
        prepared_ = true;
    }
    void deactivate() override {}

    // ---- audio thread ----
    void run(const float** inputs, float** outputs, uint32_t frames) override {
        if (!prepared_) {
            for (int c = 0; c < DISTRHO_PLUGIN_NUM_OUTPUTS; ++c)
                std::fill_n(outputs[c], frames, 0.0f);
            return;
        }
        const bool bypassed = bypassed_.load(std::memory_order_relaxed);
        for (uint32_t done = 0; done < frames;) {
            const int count =
                static_cast<int>(std::min<uint32_t>(frames - done, static_cast<uint32_t>(block_)));
            // Copied first: hosts may hand the same buffer in and out.
            const float* in[kInputs];
            for (int c = 0; c < kInputs; ++c) {
                std::copy_n(inputs[c] + done, count, input_[static_cast<size_t>(c)].data());
                in[c] = input_[static_cast<size_t>(c)].data();
            }
            float* vibration[kActuators];
            for (int k = 0; k < kActuators; ++k) vibration[k] = outputs[k] + done;
            float* music[kInputs];
            for (int c = 0; c < kInputs; ++c) music[c] = outputs[kActuators + c] + done;
            engine_.process(in, vibration, count);
            const int playing = playing_.load(std::memory_order_relaxed);
            for (int k = 0; k < kActuators; ++k)  // past the layout's outputs: faded to silence
                unused_[static_cast<size_t>(k)].process(&vibration[k], 1, count, k >= playing);
            ramp_.process(vibration, kActuators, count, bypassed);
            delay_.set_delay_samples(engine_.latency());
            delay_.process(in, music, count);
            done += static_cast<uint32_t>(count);
        }
        if (const int latency = engine_.latency(); latency != latency_samples_) {
            latency_samples_ = latency;
            setLatency(static_cast<uint32_t>(latency));
        }
    }

  private:
    static constexpr uint32_t kVibrationGroup = 1;  // DPF's own groups are kPortGroupMono, Stereo
    static constexpr uint32_t kLayoutState = 1, kStates = 2;  // after tp::kStateKey's
    static constexpr const char* kLayoutKey = "layout";

    // Main or worker thread: the layout at `path` (empty: every port plays everything) for the
    // vibration ports; a bad one is said in one line on stderr and changes nothing.
    void load_layout(const char* path) {
        std::vector<tactus::ActuatorOutput> next(kActuators);
        int playing = kActuators;
        std::string resolved;
        try {
            if (*path != '\0') {
                resolved = tactus::resolve_layout(path).string();
                const tactus::Layout layout = tactus::load_layout(resolved);
                if (layout.outputs.size() > kActuators)
                    throw std::runtime_error(
                        fmt::format("layout {} has {} outputs; the plugin plays {}", layout.name,
                                    layout.outputs.size(), kActuators));
                const std::vector<tactus::ActuatorOutput> outputs =
                    layout.actuator_outputs([this](const std::string& name) {
                        tactus::ActuatorProfile profile =
                            tactus::load_actuator(tactus::resolve_actuator(name));
                        for (const auto& warning :
                             tactus::actuator_warnings(profile, host_.settings()))
                            d_stderr2("tactus: warning: %s", warning.c_str());
                        return profile;
                    });
                std::copy(outputs.begin(), outputs.end(), next.begin());
                playing = static_cast<int>(outputs.size());
            }
            for (int k = 0; k < playing; ++k)  // a channel the ports lack, a band over Nyquist
                next[static_cast<size_t>(k)].check_input(
                    k, {.sample_rate_hz = getSampleRate(), .max_block = 1, .channels = kInputs});
            const std::lock_guard lock(engine_mutex_);
            if (prepared_)
                set_outputs_live(next);
            else
                engine_.set_actuators(next);
            outputs_ = std::move(next);
            layout_path_ = std::move(resolved);
            playing_.store(playing);
        } catch (const std::exception& e) {
            d_stderr2("tactus: layout not loaded, the last one kept: %s", e.what());
        }
    }
    // engine_mutex_ held, the engine prepared: everything but the delays now (one pipeline,
    // no gap), the delays at the next activation.
    void set_outputs_live(std::vector<tactus::ActuatorOutput> next) {
        const std::vector<tactus::ActuatorOutput> running = engine_.outputs();
        bool delays_wait = false;
        for (size_t k = 0; k < next.size(); ++k) {
            delays_wait |= next[k].delay_ms != running[k].delay_ms;
            next[k].delay_ms = running[k].delay_ms;
        }
        engine_.set_outputs(std::move(next));
        if (delays_wait) d_stderr2("tactus: the layout's delays apply at the next activation");
    }

    // Control thread: the host's changes to the engine; whether there were any.
    bool take_changes() {
        if (!host_.changed()) return false;
        const std::lock_guard lock(engine_mutex_);
        apply_changes();
        return true;
    }
    void apply_changes() {  // engine_mutex_ held; a program's changes build one pipeline
        tactus::Settings next = engine_.settings();
        host_.for_each_marked([&next](tactus::P id, double value) {
            try {
                next.set(id, value);
            } catch (const std::exception& e) {
                d_stderr2("tactus: %s", e.what());
            }
        });
        try {
            engine_.set(next);
        } catch (const std::exception& e) {
            d_stderr2("tactus: %s", e.what());
        }
    }

    std::vector<std::optional<tactus::P>> rows_;  // host parameter index -> table row
    struct Program {
        std::string_view name;
        tactus::Settings settings;
    };
    std::vector<Program> programs_;  // kFactoryPresets, read; the defaults first
    // The values the host asked for, apart from the engine's settings: hosts read and write
    // them on their audio thread (getParameterValue, setParameterValue), which must not take
    // the engine's control mutex, and they are the state saved even before the control thread
    // has handed them to the engine.
    tp::HostParameters host_;
    std::atomic<bool> bypassed_{false};
    tactus::Engine engine_;
    mutable std::mutex engine_mutex_;  // main, worker and control threads, never audio's
    // The layout: its file (empty: none), the engine's outputs as it gives them (delays
    // included, which the engine takes at activation) and how many ports play (audio thread).
    std::string layout_path_;
    std::vector<tactus::ActuatorOutput> outputs_ = std::vector<tactus::ActuatorOutput>(kActuators);
    std::atomic<int> playing_{kActuators};
    bool prepared_ = false;
    int block_ = 0;
    int latency_samples_ = 0;
    std::vector<std::vector<float>> input_;
    tactus::DelayLine delay_;  // the music, by the engine's latency
    tp::BypassRamp ramp_;
    std::array<tp::BypassRamp, kActuators> unused_;  // each port's fade when a layout leaves it
    std::unique_ptr<tp::ControlThread> control_;

    DISTRHO_DECLARE_NON_COPYABLE_WITH_LEAK_DETECTOR(TactusPlugin)
};

Plugin* createPlugin() {
    return new TactusPlugin();
}

END_NAMESPACE_DISTRHO
