#include "tactus/engine/engine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tactus/core/units.hpp"
#include "tactus/dsp/denormals.hpp"
#include "tactus/dsp/downmix.hpp"
#include "tactus/params/components.hpp"

namespace tactus {
namespace {

int64_t ceil_div(int64_t a, int64_t b) {
    return (a + b - 1) / b;
}

void check_range(std::string_view what, int value, int low, int high) {
    if (value < low || value > high)
        throw std::invalid_argument(
            fmt::format("{} {} is outside the supported {}-{}", what, value, low, high));
}

// The features the mapping reads (its sources) and the gate's loudness.
FeatureSet mapped_features(const Settings& s) {
    FeatureSet read = FeatureSet::none();
    read.loudness = true;
    for (P source : {P::amplitude_source, P::frequency_source, P::square_mix_source,
                     P::flutter_level_source, P::flutter_rate_source, P::pressure_level_source})
        read = read | group_of(static_cast<FeatureSource>(s[source]));
    return read;
}

// The parameters that shape the flattening filter: a change is designed on the control thread.
bool shapes_flattening(P id) {
    return id == P::post_flatten_strength || id == P::post_flatten_range_db ||
           id == P::post_flatten_level_db || id == P::perception_contact_area_cm2;
}

}  // namespace

Engine::Engine(Settings settings) : settings_(settings), outputs_(1) {}

void Engine::set_actuator(std::optional<ActuatorProfile> actuator) {
    set_actuators({ActuatorOutput{.profile = std::move(actuator)}});
}

void Engine::set_actuators(std::vector<ActuatorOutput> outputs) {
    check_range("actuator count", static_cast<int>(outputs.size()), 1, kMaxActuators);
    for (size_t k = 0; k < outputs.size(); ++k) outputs[k].check(static_cast<int>(k));
    // The first actuator's capability decides whether the pressure is synthesised at all.
    if (outputs.front().profile) settings_.set(P::actuator_dc, outputs.front().profile->dc);
    outputs_ = std::move(outputs);
}

void Engine::check_sample_rate(double sample_rate_hz) {
    if (!(sample_rate_hz >= kMinSampleRateHz && sample_rate_hz <= kMaxSampleRateHz))
        throw std::invalid_argument(
            fmt::format("sample rate {} Hz is outside the supported {}-{} Hz", sample_rate_hz,
                        kMinSampleRateHz, kMaxSampleRateHz));
}

void Engine::prepare(const EngineSpec& spec) {
    check_sample_rate(spec.sample_rate_hz);
    check_range("block size", spec.max_block, 1, kMaxBlock);
    check_range("input channel count", spec.input_channels, 1, kMaxInputChannels);
    check_range("input channel", spec.input_channel, -1, spec.input_channels - 1);
    spec_ = spec;
    const double rate = spec.sample_rate_hz;
    rate_divisor_ =
        std::clamp(static_cast<int>(rate / kMinInternalRateHz), 1, Upsampler::kMaxFactor);
    const ChainSpec chain{.internal_rate_hz = rate / rate_divisor_,
                          .rate_divisor = rate_divisor_,
                          .max_internal_block =
                              static_cast<int>(ceil_div(spec.max_block, rate_divisor_)) + 1,
                          .max_block = spec.max_block};
    // Actuators with the same profile share a chain.
    chains_.clear();
    chain_of_.clear();
    first_of_chain_.clear();
    trims_.resize(outputs_.size());
    for (size_t k = 0; k < outputs_.size(); ++k) {
        size_t j = 0;
        while (j < k && outputs_[j].profile != outputs_[k].profile) ++j;
        if (j == k) {
            chains_.emplace_back().prepare(chain, settings_,
                                           outputs_[k].profile ? &*outputs_[k].profile : nullptr);
            first_of_chain_.push_back(static_cast<int>(k));
            chain_of_.push_back(static_cast<int>(chains_.size()) - 1);
        } else {
            chain_of_.push_back(chain_of_[j]);
        }
        trims_[k].prepare(rate, outputs_[k]);
    }
    for (auto& c : chains_) c.set_pressure_reference(chains_.front().post().ceiling());
    const auto internal = static_cast<size_t>(chain.max_internal_block);
    carrier_.assign(internal, 0.0f);
    flutter_on_ = flutter_enabled(settings_);
    pressure_on_ = pressure_enabled(settings_);
    flutter_.assign(flutter_on_ ? internal : 0, 0.0f);
    pressure_.assign(pressure_on_ ? internal : 0, 0.0f);
    mono_.assign(spec.input_channels > 1 ? static_cast<size_t>(spec.max_block) : 0, 0.0f);
    analyzer_.prepare(rate, settings_);
    const double frames_per_second = rate / analyzer_.hop_samples();
    mapper_.prepare(settings_, frames_per_second, chains_.front().post().ceiling());
    voice_.prepare(chain.internal_rate_hz, settings_[P::post_band_high_hz]);
    live_.prepare(settings_, frames_per_second);
    update_features();
    // Whatever was queued before this prepare is in settings_ already.
    for (Change c; changes_.try_dequeue(c);) {}
    for (ControlFrame f; injected_.try_dequeue(f);) {}
    for (FlatteningFilter::Design d; designs_.try_dequeue(d);) {}
    prepared_ = true;
    reset();
}

void Engine::reset() noexcept {
    analyzer_.reset();
    mapper_.reset();
    voice_.reset();
    for (auto& chain : chains_) chain.reset();
    for (auto& trim : trims_) trim.reset();
    position_ = 0;
}

void Engine::set_observer(FrameObserver* observer) {
    observer_ = observer;
    update_features();
}

void Engine::enable_frame_queue() {
    frames_.emplace(kQueueCapacity);
}

// The analysis computes what the mapping or the observer reads.
void Engine::update_features() noexcept {
    FeatureSet read = mapped_features(live_.now());
    if (observer_) read = read | observer_->reads();
    if (frames_) read = read | FeatureSet{};
    analyzer_.set_features(read);
}

int Engine::latency() const {
    if (chains_.empty()) return 0;
    const ActuatorChain& chain = chains_.front();
    return chain.post().latency_samples() * rate_divisor_ +
           static_cast<int>(std::lround(chain.upsampler().delay_samples()));
}

int64_t Engine::clipped_samples() const {
    int64_t clipped = 0;
    for (const auto& chain : chains_) clipped += chain.clipped_samples();
    return clipped;
}

// ---- control threads ----

void Engine::send(const Change& change) {
    if (!changes_.try_enqueue(change))
        throw std::runtime_error("engine: too many changes waiting for the audio thread");
}

void Engine::set(P id, double value) {
    const std::lock_guard lock(control_);
    Settings next = settings_;
    next.set(id, value);  // throws std::invalid_argument naming the key
    if (prepared_) {
        if (tactus::spec(id).change == ParamChange::structural ||
            flutter_enabled(next) != flutter_on_ || pressure_enabled(next) != pressure_on_)
            throw std::logic_error(fmt::format(
                "{} changes the engine's structure: prepare() the engine again",
                tactus::spec(id).key));
        if (shapes_flattening(id) &&
            !designs_.try_enqueue(chains_.front().post().flattening_design(next)))
            throw std::runtime_error("engine: too many changes waiting for the audio thread");
        send({Change::Kind::parameter, static_cast<int>(id), next[id]});
    }
    settings_ = next;
}

void Engine::set_actuator_gain_db(int actuator, double gain_db) {
    const std::lock_guard lock(control_);
    check_range("actuator", actuator, 0, actuators() - 1);
    ActuatorOutput output = outputs_[static_cast<size_t>(actuator)];
    output.gain_db = gain_db;
    output.check(actuator);
    if (prepared_) send({Change::Kind::actuator_gain, actuator, gain_db});
    outputs_[static_cast<size_t>(actuator)] = output;
}

void Engine::inject(const ControlFrame& frame) {
    const std::lock_guard lock(control_);
    if (!injected_.try_enqueue(frame))
        throw std::runtime_error("engine: too many control frames waiting for the audio thread");
}

void Engine::trigger(double frequency_hz, double amplitude) {
    if (!(frequency_hz > 0 && frequency_hz <= tactus::spec(P::frequency_out_max).max) ||
        !(amplitude >= 0 && amplitude <= 1))
        throw std::invalid_argument(fmt::format(
            "trigger {} Hz, amplitude {}: allowed 0-{} Hz and amplitude 0-1", frequency_hz,
            amplitude, tactus::spec(P::frequency_out_max).max));
    ControlFrame frame;
    {
        const std::lock_guard lock(control_);
        frame.attack_ms = settings_[P::envelope_attack_ms];
        frame.decay_ms = settings_[P::envelope_decay_ms];
        frame.sustain = settings_[P::envelope_sustain];
    }
    frame.frequency_hz = frequency_hz;
    frame.amplitude = amplitude;
    frame.trigger = true;
    inject(frame);
}

void Engine::set_program_source(ProgramSource source) {
    const std::lock_guard lock(control_);
    send({Change::Kind::program_source, static_cast<int>(source), 0.0});
}

bool Engine::pop_frame(AnalysisFrame& frame) {
    return frames_ && frames_->try_dequeue(frame);
}

// ---- audio thread ----

void Engine::take_changes() noexcept {
    for (Change c; changes_.try_dequeue(c);) {
        switch (c.kind) {
            case Change::Kind::parameter:
                live_.ask(static_cast<P>(c.index), c.value);
                break;
            case Change::Kind::actuator_gain:
                trims_[static_cast<size_t>(c.index)].set_gain_db(c.value);
                break;
            case Change::Kind::program_source:
                source_ = static_cast<ProgramSource>(c.index);
                break;
        }
    }
    for (FlatteningFilter::Design d; designs_.try_dequeue(d);) {
        const int glide_samples = static_cast<int>(ms_to_samples(
            tactus::spec(P::post_flatten_strength).smoothing_ms, spec_.sample_rate_hz / rate_divisor_));
        for (auto& chain : chains_) chain.post().glide_flattening(d, glide_samples);
    }
    if (live_.take_changed()) apply_live();
}

// The stages take the live settings as they now are; the post chains at the end of the chunk.
void Engine::apply_live() noexcept {
    const Settings& s = live_.now();
    analyzer_.set_live(s);
    mapper_.set_live(s, chains_.front().post().ceiling_for(s));
    update_features();
    post_dirty_ = true;
}

const float* Engine::downmix(const float* const* in, int offset, int count) noexcept {
    const int channels = spec_.input_channels;
    if (channels == 1) return in[0] + offset;
    if (spec_.input_channel >= 0) return in[spec_.input_channel] + offset;
    downmix_mean(in, channels, offset, mono_.data(), count);
    return mono_.data();
}

void Engine::process(const float* const* in, float* const* out, int count) noexcept {
    const ScopedFlushDenormals no_denormals;
    take_changes();
    for (int done = 0; done < count;) {
        const int chunk = std::min(count - done, spec_.max_block);
        process_chunk(in, out, done, chunk);
        done += chunk;
    }
}

void Engine::process_chunk(const float* const* in, float* const* out, int offset,
                           int count) noexcept {
    const float* mono = downmix(in, offset, count);
    for (ControlFrame frame; injected_.try_dequeue(frame);) {
        frame.sample = position_;
        voice_.apply(frame);
    }
    const int divisor = rate_divisor_;
    float* const flutter = flutter_.empty() ? nullptr : flutter_.data();
    float* const pressure = pressure_.empty() ? nullptr : pressure_.data();
    int done = 0, rendered = 0;
    while (done < count) {
        const int chunk = std::min(count - done, analyzer_.samples_to_next_frame());
        const bool frame_due = analyzer_.write(mono + done, chunk);
        // Internal sample k stands at input sample k * divisor.
        const auto due =
            static_cast<int>(ceil_div(position_ + chunk, divisor) - ceil_div(position_, divisor));
        voice_.render(carrier_.data() + rendered, flutter ? flutter + rendered : nullptr,
                      pressure ? pressure + rendered : nullptr, due);
        rendered += due;
        position_ += chunk;
        if (frame_due) {
            if (live_.gliding() && live_.step()) apply_live();
            const Features& features = analyzer_.analyse();
            const ControlFrame control = mapper_.map(features);
            if (source_ != ProgramSource::external) voice_.apply(control);
            if (observer_) observer_->on_frame(features, control);
            if (frames_) frames_->try_enqueue({features, control});  // dropped when full
        }
        done += chunk;
    }
    if (post_dirty_) {  // glides over an analysis frame: LiveSettings' steps join up
        const int glide = std::max(rendered, hop_samples() / divisor);
        for (auto& chain : chains_) chain.set_live(live_.now(), glide);
        for (auto& chain : chains_) chain.set_pressure_reference(chains_.front().post().ceiling());
        post_dirty_ = false;
    }
    for (size_t j = 0; j < chains_.size(); ++j) {
        const bool last = j + 1 == chains_.size();
        chains_[j].process(carrier_.data(), flutter, pressure, rendered, last,
                           out[first_of_chain_[j]] + offset, count);
    }
    for (size_t k = 0; k < trims_.size(); ++k) {  // copies first, then each its own trim
        const int first = first_of_chain_[static_cast<size_t>(chain_of_[k])];
        if (first != static_cast<int>(k)) std::copy_n(out[first] + offset, count, out[k] + offset);
    }
    for (size_t k = 0; k < trims_.size(); ++k) trims_[k].process(out[k] + offset, count);
}

}  // namespace tactus
