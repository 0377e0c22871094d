#include "tactus_plugin.hpp"

#include <vamp-sdk/PluginAdapter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tactus/io/actuator_file.hpp"
#include "tactus/io/preset.hpp"

namespace tactus::vamp {
namespace {

using Column = size_t;
// A per-frame output: its identifier, what it shows, its unit and the analyze column(s) it reads.
struct FrameOutput {
    const char* identifier;
    const char* name;
    const char* unit;
    std::vector<std::string_view> columns;
};

const std::vector<FrameOutput>& frame_outputs() {
    static const std::vector<FrameOutput> outputs = {
        {"loudness", "Loudness (K-weighted, short window)", "dB", {"loudness_db"}},
        {"brightness", "Brightness (spectral centroid)", "Hz", {"brightness_hz"}},
        {"noisiness", "Noisiness (Bark-band spectral flatness)", "", {"noisiness"}},
        {"pitch", "Pitch (YIN; 0 unvoiced)", "Hz", {"pitch_hz"}},
        {"vibration_frequency", "Vibration frequency", "Hz", {"frequency_hz"}},
        {"vibration_amplitude", "Vibration amplitude", "", {"amplitude"}},
        {"sensation",
         "Sensation level per channel of touch",
         "dB SL",
         {"P_sl_db", "NPI_sl_db", "NPII_sl_db", "NPIII_sl_db", "combined_sl_db"}},
    };
    return outputs;
}

Column column(std::string_view name) {
    return AnalysisRows::column(name);
}

const ParamSpec* spec_named(const std::string& identifier) {
    for (const ParamSpec& s : param_table())
        if (identifier_of(s) == identifier) return &s;
    return nullptr;
}

Vamp::RealTime at_seconds(double seconds) {
    return Vamp::RealTime::fromSeconds(seconds);
}

}  // namespace

TactusPlugin::TactusPlugin(float input_sample_rate) : Plugin(input_sample_rate) {
    selectProgram(kDefaultPreset);
}

TactusPlugin::~TactusPlugin() = default;

std::string TactusPlugin::getDescription() const {
    return "Onsets, loudness, brightness, noisiness, pitch, the vibration frequency and "
           "amplitude, and the sensation level per channel of touch (P, NPI, NPII, NPIII) the "
           "vibration gives through a voice-coil actuator (Birnbaum & Wanderley)";
}

Vamp::Plugin::ParameterList TactusPlugin::getParameterDescriptors() const {
    ParameterList list;
    const Settings defaults;
    for (const ParamSpec& s : param_table()) {
        ParameterDescriptor d;
        d.identifier = identifier_of(s);
        d.name = std::string(s.key);
        d.description = std::string(s.help);
        d.unit = std::string(s.unit);
        d.minValue = static_cast<float>(s.min);
        d.maxValue = static_cast<float>(s.max);
        d.defaultValue = static_cast<float>(defaults[s.param]);
        d.isQuantized = s.type != ParamType::real;
        d.quantizeStep = d.isQuantized ? 1.0f : 0.0f;
        for (auto c : s.choices) d.valueNames.emplace_back(c);
        list.push_back(d);
    }
    return list;
}

float TactusPlugin::getParameter(std::string identifier) const {
    const ParamSpec* s = spec_named(identifier);
    return s ? static_cast<float>(settings_[s->param]) : 0.0f;
}

void TactusPlugin::setParameter(std::string identifier, float value) {
    const ParamSpec* s = spec_named(identifier);
    if (!s) return;
    // A host handing back the float it was given keeps the preset's exact value.
    if (value == static_cast<float>(settings_[s->param])) return;
    try {
        settings_.set(s->param, value);
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "tactus: %s\n", e.what());
    }
}

Vamp::Plugin::ProgramList TactusPlugin::getPrograms() const {
    ProgramList programs;
    for (const PresetInfo& p : list_presets()) programs.push_back(p.name);
    return programs;
}

void TactusPlugin::selectProgram(std::string name) {
    Settings settings;
    try {
        apply_preset_file(settings, resolve_preset(name));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tactus: %s; the table's defaults instead\n", e.what());
        name.clear();
    }
    settings_ = settings;
    program_ = name;
}

Vamp::Plugin::OutputList TactusPlugin::getOutputDescriptors() const {
    const double hop =
        engine_ ? engine_->hop_samples() : Analyzer::hop_samples_for(settings_, m_inputSampleRate);
    OutputList list;
    OutputDescriptor onsets;
    onsets.identifier = "onsets";
    onsets.name = "Onsets";
    onsets.description =
        "Onsets as `tactus onsets` prints them: at the estimated start, with the time it was "
        "decided (s) and the hit's strength (dB), labelled with its drum part (kick, snare, hat, "
        "other)";
    onsets.hasFixedBinCount = true;
    onsets.binCount = 2;
    onsets.binNames = {"decided_s", "strength_db"};
    onsets.sampleType = OutputDescriptor::VariableSampleRate;
    onsets.sampleRate = static_cast<float>(m_inputSampleRate / hop);
    list.push_back(onsets);
    for (const FrameOutput& o : frame_outputs()) {
        OutputDescriptor d;
        d.identifier = o.identifier;
        d.name = o.name;
        d.unit = o.unit;
        d.hasFixedBinCount = true;
        d.binCount = o.columns.size();
        if (o.columns.size() > 1)
            for (auto c : o.columns) d.binNames.emplace_back(c.substr(0, c.find("_sl_db")));
        // Frames end at whole input samples, hop samples apart on average but not on a fixed
        // grid (the analysis hop is whole 16 kHz samples): timestamped, to the input sample.
        d.sampleType = OutputDescriptor::VariableSampleRate;
        d.sampleRate = static_cast<float>(m_inputSampleRate);
        list.push_back(d);
    }
    return list;
}

bool TactusPlugin::initialise(size_t channels, size_t step_size, size_t block_size) {
    if (channels < getMinChannelCount() || channels > getMaxChannelCount() || block_size == 0 ||
        step_size != block_size)
        return false;
    channels_ = channels;
    block_size_ = block_size;
    try {
        start();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tactus: %s\n", e.what());
        return false;
    }
    return true;
}

void TactusPlugin::start() {
    engine_ = std::make_unique<Engine>(settings_);
    engine_->set_actuator(std::nullopt);
    engine_->enable_frame_queue();
    rows_ = std::make_unique<AnalysisRows>(
        *engine_, load_actuator(resolve_actuator(kDefaultActuator)),
        [this](const AnalysisRows::Row& row) { add_row(row); },
        [this](const DecidedOnset& onset) { add_onset(onset); });
    // Blocks of up to kMaxBlock: the frame queue holds every frame of one.
    const int max_block = static_cast<int>(std::min<size_t>(block_size_, Engine::kMaxBlock));
    engine_->prepare({.sample_rate_hz = m_inputSampleRate,
                      .max_block = max_block,
                      .channels = static_cast<int>(channels_)});
    rows_->start(m_inputSampleRate);
    vibration_.assign(static_cast<size_t>(max_block), 0.0f);
}

void TactusPlugin::reset() {
    if (engine_) start();
}

// An onset at its estimated start, labelled with its part, as `tactus onsets` prints it.
void TactusPlugin::add_onset(const DecidedOnset& onset) {
    Feature f;
    f.hasTimestamp = true;
    f.timestamp = at_seconds(static_cast<double>(onset.onset_sample) / m_inputSampleRate);
    f.values = {static_cast<float>(static_cast<double>(onset.decided_sample) / m_inputSampleRate),
                static_cast<float>(onset.strength_db)};
    f.label = std::string(name_of(onset.part));
    pending_[0].push_back(f);
}

void TactusPlugin::add_row(const AnalysisRows::Row& row) {
    const Vamp::RealTime time = at_seconds(row[column("time_s")]);
    int output = 1;
    for (const FrameOutput& o : frame_outputs()) {
        Feature f;
        f.hasTimestamp = true;
        f.timestamp = time;
        for (auto c : o.columns) f.values.push_back(static_cast<float>(row[column(c)]));
        pending_[output++].push_back(f);
    }
}

Vamp::Plugin::FeatureSet TactusPlugin::process(const float* const* input_buffers, Vamp::RealTime) {
    const int max_block = static_cast<int>(vibration_.size());
    std::vector<const float*> in(channels_);
    float* out = vibration_.data();
    for (int done = 0; done < static_cast<int>(block_size_); done += max_block) {
        const int count = std::min(max_block, static_cast<int>(block_size_) - done);
        for (size_t c = 0; c < channels_; ++c) in[c] = input_buffers[c] + done;
        engine_->process(in.data(), &out, count);
        rows_->take_frames(*engine_);
        rows_->vibration(out, count);
    }
    return std::exchange(pending_, {});
}

Vamp::Plugin::FeatureSet TactusPlugin::getRemainingFeatures() {
    rows_->finish();
    return std::exchange(pending_, {});
}

}  // namespace tactus::vamp

extern "C" __attribute__((visibility("default"))) const VampPluginDescriptor*
vampGetPluginDescriptor(unsigned int version, unsigned int index) {
    if (version < 1) return nullptr;
    static Vamp::PluginAdapter<tactus::vamp::TactusPlugin> adapter;
    return index == 0 ? adapter.getDescriptor() : nullptr;
}
