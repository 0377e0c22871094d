#include "tactus/engine/engine.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "tactus/actuator/fit.hpp"
#include "tactus/core/units.hpp"
#include "tactus/dsp/denormals.hpp"
#include "tactus/dsp/downmix.hpp"
#include "tactus/params/components.hpp"

namespace tactus {
namespace {

void check_range(std::string_view what, int value, int low, int high) {
    if (value < low || value > high)
        throw std::invalid_argument(
            fmt::format("{} {} is outside the supported {}-{}", what, value, low, high));
}

// The parameters that shape the flattening filter: a change is designed on the control thread.
bool shapes_flattening(P id) {
    return id == P::post_flatten_strength || id == P::post_flatten_range_db ||
           id == P::post_flatten_level_db || id == P::perception_contact_area_cm2;
}

}  // namespace

Engine::Engine(Settings settings) : settings_(settings), outputs_(1) {}

Engine::~Engine() {
    for (Change c; changes_.try_dequeue(c);) delete c.pipeline;
    delete waiting_.pipeline;
    delete incoming_;
    free_retired();
}

void Engine::set_actuator(std::optional<ActuatorProfile> actuator) {
    set_actuators({ActuatorOutput{.profile = std::move(actuator)}});
}

void Engine::set_actuators(std::vector<ActuatorOutput> outputs) {
    check_range("actuator count", static_cast<int>(outputs.size()), 1, kMaxActuators);
    for (size_t k = 0; k < outputs.size(); ++k) outputs[k].check(static_cast<int>(k));
    const Settings next = with_first_dc(settings_, outputs);
    if (next != settings_) ++version_;
    settings_ = next;
    outputs_ = std::move(outputs);
}

// The first actuator's capability decides whether the pressure is synthesised at all: its dc
// replaces actuator.dc (an output without a profile keeps the setting).
Settings Engine::with_first_dc(Settings settings, const std::vector<ActuatorOutput>& outputs) {
    if (outputs.front().profile) settings.set(P::actuator_dc, outputs.front().profile->dc);
    return settings;
}

void Engine::check_sample_rate(double sample_rate_hz) {
    if (!(sample_rate_hz >= kMinSampleRateHz && sample_rate_hz <= kMaxSampleRateHz))
        throw std::invalid_argument(
            fmt::format("sample rate {} Hz is outside the supported {}-{} Hz", sample_rate_hz,
                        kMinSampleRateHz, kMaxSampleRateHz));
}

// What the pipeline runs: the settings fitted to the first actuator's profile (actuator/fit.hpp),
// as its dc decides the pressure.
Settings Engine::fitted(const Settings& settings) const {
    const auto& profile = outputs_.front().profile;
    return profile ? fit_to_actuator(*profile, settings).settings : settings;
}

// The outputs as the pipeline plays them: each one's overlay becomes what its own settings (the
// settings with its overlay, fitted to its own profile) differ in from the pipeline's (fitted to
// the first output's profile), so each actuator plays its own fit, and an overlay is fitted too
// (an LRA's output asking for 500-1000 Hz plays inside its band). Empty for an output playing the
// pipeline's settings, as the first one does without an overlay.
std::vector<ActuatorOutput> Engine::as_played(const Settings& settings) const {
    const Settings base = fitted(settings);
    std::vector<ActuatorOutput> played = outputs_;
    for (ActuatorOutput& o : played) {
        Settings own = overlaid(settings, o.overlay);
        if (o.profile) {
            own.set(P::actuator_dc, o.profile->dc);
            own = fit_to_actuator(*o.profile, own).settings;
        }
        o.overlay.clear();
        for (const ParamSpec& s : param_table())
            if (own[s.param] != base[s.param]) o.overlay.emplace_back(s.param, own[s.param]);
    }
    return played;
}

std::unique_ptr<Pipeline> Engine::make_pipeline(const Settings& settings, int64_t origin,
                                                int max_block) const {
    auto pipeline = std::make_unique<Pipeline>();
    pipeline->prepare({.sample_rate_hz = spec_.sample_rate_hz, .max_block = max_block},
                      fitted(settings), as_played(settings), origin);
    pipeline->set_extra_features(extra_features());
    pipeline->set_source(source_);
    pipeline->replay(recording_.get());
    return pipeline;
}

void Engine::prepare(const ProcessSpec& spec) {
    check_sample_rate(spec.sample_rate_hz);
    check_range("block size", spec.max_block, 1, kMaxBlock);
    check_range("input channel count", spec.channels, 1, kMaxInputChannels);
    check_range("input channel", input_channel_, -1, spec.channels - 1);
    for (size_t k = 0; k < outputs_.size(); ++k) outputs_[k].check_input(static_cast<int>(k), spec);
    spec_ = spec;
    for (Change c; changes_.try_dequeue(c);) delete c.pipeline;  // settings_ holds them
    for (ControlFrame f; injected_.try_dequeue(f);) {
    }
    delete std::exchange(waiting_.pipeline, nullptr);
    delete std::exchange(incoming_, nullptr);
    free_retired();
    active_ = make_pipeline(settings_, 0, spec.max_block);
    rate_divisor_ = active_->rate_divisor();
    trims_.resize(outputs_.size());
    for (size_t k = 0; k < outputs_.size(); ++k) trims_[k].prepare(spec, outputs_[k]);
    const auto block = static_cast<size_t>(spec.max_block);
    mono_.assign(spec.channels > 1 ? block : 0, 0.0f);
    incoming_out_.assign(outputs_.size(), std::vector<float>(block));
    incoming_pointers_.resize(outputs_.size());
    mono_catch_up_.assign(block, 0.0f);
    for (size_t k = 0; k < outputs_.size(); ++k) incoming_pointers_[k] = incoming_out_[k].data();
    fade_samples_ =
        std::max<int>(1, static_cast<int>(ms_to_samples(kCrossfadeMs, spec.sample_rate_hz)));
    summed_loudness_ = spec.channels > 1 && input_channel_ < 0;
    if (summed_loudness_) channel_power_.prepare(spec);
    routed_channels_ = spec.channels > 1 ? std::min(spec.channels, Route::kMaxChannel) : 0;
    ring_.prepare(first_channel_lane() + routed_channels_,
                  ms_to_samples(2e3 * kPrimeSeconds, spec.sample_rate_hz), spec.max_block);
    channels_catch_up_.assign(static_cast<size_t>(routed_channels_), std::vector<float>(block));
    power_.assign(summed_loudness_ ? block : 0, 0.0f);
    power_catch_up_.assign(power_.size(), 0.0f);
    prepared_ = true;
    reset();
}

void Engine::reset() noexcept {
    if (!active_) return;
    delete std::exchange(waiting_.pipeline, nullptr);  // setup thread: no audio thread runs
    delete std::exchange(incoming_, nullptr);
    active_->reset();
    for (auto& trim : trims_) trim.reset();
    ring_.reset();
    channel_power_.reset();
    latency_ = active_->latency();
    hop_samples_ = active_->hop_samples();
}

void Engine::set_observer(FrameObserver* observer) {
    observer_ = observer;
    if (active_) active_->set_extra_features(extra_features());
}

void Engine::replay_analysis(std::shared_ptr<const RecordedAnalysis> recording) {
    recording_ = std::move(recording);
    if (active_) active_->replay(recording_.get());
}

void Engine::enable_frame_queue() {
    frames_.emplace(kQueueCapacity);
    lane_frames_.emplace(kQueueCapacity);
    if (active_) active_->set_extra_features(extra_features());
}

// What the engine's readers read besides the mapping's features: all, for the frame queue.
FeatureSet Engine::extra_features() const {
    FeatureSet read = observer_ ? observer_->reads() : FeatureSet::none();
    return frames_ ? read | FeatureSet{} : read;
}

void Engine::FrameForwarder::on_frame(const Features& features,
                                      const ControlFrame& control) noexcept {
    if (engine_.observer_) engine_.observer_->on_frame(features, control);
    if (engine_.frames_) engine_.frames_->try_enqueue({features, control});  // dropped when full
}

void Engine::FrameForwarder::on_lane_frame(int lane, const ControlFrame& control) noexcept {
    if (engine_.observer_) engine_.observer_->on_lane_frame(lane, control);
    if (engine_.lane_frames_)
        engine_.lane_frames_->try_enqueue({lane, control});  // dropped when full
}

// ---- control threads ----

void Engine::send(const Change& change) {
    if (!changes_.try_enqueue(change))
        throw std::runtime_error("engine: too many changes waiting for the audio thread");
}

void Engine::free_retired() {
    for (Pipeline* p; retired_.try_dequeue(p);) delete p;
}

void Engine::set(P id, double value) {
    const std::lock_guard lock(control_);
    Settings next = settings_;
    next.set(id, value);  // throws std::invalid_argument naming the key
    commit(next);
}

void Engine::set(const Settings& next) {
    const std::lock_guard lock(control_);
    commit(next);
}

SettingsSnapshot Engine::settings_snapshot() const {
    const std::lock_guard lock(control_);
    return {.settings = settings_, .version = version_};
}

// control_ held: applies, and gives the settings a new version when they changed.
void Engine::commit(const Settings& next) {
    if (next == settings_) return;
    apply(next);  // changes settings_ wholly or, when it throws, not at all
    ++version_;
}

// control_ held. A value the engine already has changes nothing (a restored state or a program
// sets every parameter: a structural one would otherwise build a pipeline for nothing); any
// structural difference builds one pipeline with all of them; live ones go one by one. Nothing
// is sent unless the queue has room for every change (only control threads, one at a time,
// fill it; the audio thread only empties it), so a full queue throws having changed nothing and
// settings_ always says what the audio thread got.
// The running pipeline has the settings fitted to the actuator (actuator/fit.hpp): what is
// compared and sent is what the fit makes of them (a parameter and those derived from it).
void Engine::apply(const Settings& next) {
    if (!prepared_) {
        settings_ = next;
        return;
    }
    free_retired();
    const Settings was = fitted(settings_), now = fitted(next);
    // -1: a new pipeline, one change (also when an output's own values change with it)
    const int needed = as_played(settings_) == as_played(next) ? changes_needed(was, now) : -1;
    if (static_cast<int>(changes_.size_approx()) + std::max(needed, 1) > kChangeCapacity)
        throw std::runtime_error("engine: too many changes waiting for the audio thread");
    if (needed < 0) {
        swap_in(next);
        settings_ = next;
        return;
    }
    Settings sent = was;  // what the audio thread has
    for (const ParamSpec& s : param_table()) {
        const P id = s.param;
        if (now[id] != sent[id]) {
            Change change{.kind = Change::Kind::parameter, .param = id, .value = now[id]};
            if (shapes_flattening(id)) {
                Settings designed = sent;
                designed.assign(id, now[id]);
                change.kind = Change::Kind::flattening;
                change.design = flattening_design(spec_.sample_rate_hz / rate_divisor_, designed);
            }
            send(change);  // cannot fail: room was checked
            sent.assign(id, now[id]);
        }
    }
    settings_ = next;
}

// The live changes from `was` to `now` (fitted settings), or -1 when a structural difference
// builds a new pipeline (one change).
int Engine::changes_needed(const Settings& was, const Settings& now) const {
    if (flutter_enabled(now) != flutter_enabled(was) ||
        pressure_enabled(now) != pressure_enabled(was))
        return -1;
    int live = 0;
    for (const ParamSpec& s : param_table()) {
        if (now[s.param] == was[s.param]) continue;
        if (s.change == ParamChange::structural) return -1;
        ++live;
    }
    return live;
}

// What each stage remembers, to -60 dB where it fades (a one-pole time constant: 6.9 of them) or
// whole where it is a window: the analysis's windows, onset history, refractory interval and
// part decision; the smoothing of the mappings in use; the envelope's decay (60 dB in decay_ms);
// the limiter's release; and the crossfade the new pipeline is heard through.
double Engine::prime_seconds(const Settings& s) {
    constexpr double kTimeConstantsTo60Db = 6.908;  // ln(1000)
    double smoothing_ms = std::max({s[P::amplitude_smoothing_ms], s[P::frequency_smoothing_ms],
                                    s[P::square_mix_smoothing_ms]});
    if (flutter_enabled(s))
        smoothing_ms = std::max(
            {smoothing_ms, s[P::flutter_level_smoothing_ms], s[P::flutter_rate_smoothing_ms]});
    if (pressure_enabled(s))
        smoothing_ms = std::max(smoothing_ms, s[P::pressure_level_smoothing_ms]);
    const double analysis_ms = s[P::analysis_window_ms] + s[P::loudness_window_ms] +
                               s[P::onset_window_ms] + s[P::onset_history_ms] +
                               s[P::onset_min_interval_ms] + s[P::parts_settle_ms];
    const double longest_ms =
        std::max({analysis_ms, kTimeConstantsTo60Db * smoothing_ms, s[P::envelope_decay_ms],
                  kTimeConstantsTo60Db * s[P::post_release_ms]});
    return std::min(kPrimeSeconds, (longest_ms + kCrossfadeMs) * 1e-3);
}

// A pipeline for `settings`, primed with the input the running one has heard, handed to the
// audio thread (which catches it up and crossfades to it).
void Engine::swap_in(const Settings& settings) {
    const auto prime = static_cast<int64_t>(prime_seconds(settings) * spec_.sample_rate_hz);
    // The new pipeline starts on the grids one with these settings from the first sample has
    // (analysis frames: Analyzer::frame_grid_samples; an internal sample every rate_divisor_
    // input samples), so a change that keeps the hop keeps every frame and onset time.
    const int64_t grid = std::lcm(Analyzer::frame_grid_samples(settings, spec_.sample_rate_hz),
                                  int64_t{rate_divisor_});
    std::vector<std::vector<float>> past(static_cast<size_t>(ring_.lanes()));
    std::vector<float*> lanes(past.size());
    int64_t to = 0, from = 0;
    for (int attempt = 0;; ++attempt) {  // the audio thread may overwrite what is being read
        to = ring_.written();
        from = std::max<int64_t>(0, to - prime);
        from -= from % grid;
        for (size_t l = 0; l < past.size(); ++l) {
            past[l].resize(static_cast<size_t>(to - from));
            lanes[l] = past[l].data();
        }
        if (ring_.read(from, lanes.data(), static_cast<int>(to - from)) || attempt == 3) break;
    }
    const int prime_block = std::max(spec_.max_block, kPrimeBlock);
    std::unique_ptr<Pipeline> pipeline = make_pipeline(settings, from, prime_block);
    std::vector<std::vector<float>> scratch(outputs_.size(),
                                            std::vector<float>(static_cast<size_t>(prime_block)));
    std::vector<float*> out(outputs_.size());
    for (size_t k = 0; k < out.size(); ++k) out[k] = scratch[k].data();
    {
        const ScopedFlushDenormals no_denormals;
        const float* channels[Route::kMaxChannel];
        for (int64_t done = 0; done < to - from;) {
            const int count = static_cast<int>(std::min<int64_t>(to - from - done, prime_block));
            pipeline->process(input_from(lanes.data(), static_cast<int>(done), channels),
                              out.data(), count, nullptr);
            done += count;
        }
    }
    send({.kind = Change::Kind::pipeline, .pipeline = pipeline.get(), .primed_to = to});
    // The audio thread owns it now; it comes back through retired_.
    static_cast<void>(pipeline.release());
}

void Engine::set_actuator_gain_db(int actuator, double gain_db) {
    const std::lock_guard lock(control_);
    check_range("actuator", actuator, 0, actuators() - 1);
    ActuatorOutput output = outputs_[static_cast<size_t>(actuator)];
    output.gain_db = gain_db;
    output.check(actuator);
    if (prepared_)
        send({.kind = Change::Kind::actuator_gain, .actuator = actuator, .gain_db = gain_db});
    outputs_[static_cast<size_t>(actuator)] = output;
}

void Engine::set_route(int actuator, const Route& route) {
    const std::lock_guard lock(control_);
    check_range("actuator", actuator, 0, actuators() - 1);
    std::vector<ActuatorOutput> next = outputs_;
    next[static_cast<size_t>(actuator)].route = route;
    apply_outputs(std::move(next));
}

void Engine::set_outputs(std::vector<ActuatorOutput> outputs) {
    const std::lock_guard lock(control_);
    apply_outputs(std::move(outputs));
}

std::vector<ActuatorOutput> Engine::outputs() const {
    const std::lock_guard lock(control_);
    return outputs_;
}

// control_ held: checks every output, then sends the trims that changed and swaps in one
// pipeline playing the routes, overlays and profiles (or, before prepare, keeps them); throws
// having changed nothing.
void Engine::apply_outputs(std::vector<ActuatorOutput> next) {
    check_range("output count", static_cast<int>(next.size()), actuators(), actuators());
    for (size_t k = 0; k < next.size(); ++k) {
        const auto index = static_cast<int>(k);
        next[k].check(index);
        if (!prepared_) continue;
        next[k].check_input(index, spec_);
        if (next[k].delay_ms != outputs_[k].delay_ms)
            throw std::invalid_argument(fmt::format(
                "actuator {}: delay {} ms: a delay is set before prepare (it plays {} ms)", index,
                next[k].delay_ms, outputs_[k].delay_ms));
    }
    if (!prepared_) return set_actuators(std::move(next));
    const Settings settings = with_first_dc(settings_, next);
    bool rebuild = settings != settings_;
    int gains = 0;
    for (size_t k = 0; k < next.size(); ++k) {
        rebuild |= next[k].profile != outputs_[k].profile || next[k].route != outputs_[k].route ||
                   next[k].overlay != outputs_[k].overlay;
        gains += next[k].gain_db != outputs_[k].gain_db ? 1 : 0;
    }
    free_retired();
    if (static_cast<int>(changes_.size_approx()) + gains + (rebuild ? 1 : 0) > kChangeCapacity)
        throw std::runtime_error("engine: too many changes waiting for the audio thread");
    for (size_t k = 0; k < next.size(); ++k)
        if (next[k].gain_db != outputs_[k].gain_db)
            send({.kind = Change::Kind::actuator_gain,
                  .actuator = static_cast<int>(k),
                  .gain_db = next[k].gain_db});  // cannot fail: room was checked
    // Element by element: the audio thread never reads outputs_, but actuators() may.
    for (size_t k = 0; k < next.size(); ++k) outputs_[k] = std::move(next[k]);
    if (rebuild) swap_in(settings);
    if (settings != settings_) ++version_;
    settings_ = settings;
}

void Engine::inject(const ControlFrame& frame) {
    const std::lock_guard lock(control_);
    if (!injected_.try_enqueue(frame))
        throw std::runtime_error("engine: too many control frames waiting for the audio thread");
}

void Engine::check_trigger(double frequency_hz, double amplitude) {
    const double highest_hz = tactus::spec(P::frequency_out_max).max;
    if (!(frequency_hz > 0 && frequency_hz <= highest_hz) || !(amplitude >= 0 && amplitude <= 1))
        throw std::invalid_argument(
            fmt::format("trigger {} Hz, amplitude {}: allowed 0-{} Hz and amplitude 0-1",
                        frequency_hz, amplitude, highest_hz));
}

void Engine::trigger(double frequency_hz, double amplitude) {
    check_trigger(frequency_hz, amplitude);
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
    source_ = source;
    if (prepared_) send({.kind = Change::Kind::program_source, .source = source});
}

bool Engine::pop_frame(AnalysisFrame& frame) {
    return frames_ && frames_->try_dequeue(frame);
}

bool Engine::pop_lane_frame(LaneFrame& frame) {
    return lane_frames_ && lane_frames_->try_dequeue(frame);
}

// ---- audio thread ----

void Engine::retire(Pipeline* pipeline) noexcept {
    // Freed on a control thread (set() frees what came back before it swaps again, prepare(),
    // the destructor), so at most a few wait here.
    if (pipeline) retired_.try_enqueue(pipeline);
}

void Engine::apply_queued_changes() noexcept {
    for (Change c; changes_.try_dequeue(c);) {
        Pipeline* const running[] = {active_.get(), incoming_, waiting_.pipeline};
        switch (c.kind) {
            case Change::Kind::parameter:
                for (Pipeline* p : running)
                    if (p) p->ask(c.param, c.value);
                break;
            case Change::Kind::flattening:
                for (Pipeline* p : running)
                    if (p) {
                        p->ask(c.param, c.value);
                        p->glide_flattening(c.design);
                    }
                break;
            case Change::Kind::actuator_gain:
                trims_[static_cast<size_t>(c.actuator)].set_gain_db(c.gain_db);
                break;
            case Change::Kind::program_source:
                for (Pipeline* p : running)
                    if (p) p->set_source(c.source);
                break;
            case Change::Kind::pipeline:
                retire(std::exchange(waiting_.pipeline, nullptr));  // superseded
                waiting_ = c;
                break;
        }
    }
    if (!incoming_ && waiting_.pipeline) start_crossfade();
    for (ControlFrame frame; injected_.try_dequeue(frame);) {
        active_->apply(frame);
        if (incoming_) incoming_->apply(frame);
    }
}

// The waiting pipeline hears the input since it was primed (the ring still holds it), then
// fades in.
void Engine::start_crossfade() noexcept {
    Pipeline* p = std::exchange(waiting_.pipeline, nullptr);
    const int block = spec_.max_block;
    for (int64_t at = p->position(); at < ring_.written();) {
        const int count = static_cast<int>(std::min<int64_t>(block, ring_.written() - at));
        float* lanes[2 + Route::kMaxChannel] = {mono_catch_up_.data()};
        if (summed_loudness_) lanes[1] = power_catch_up_.data();
        for (int c = 0; c < routed_channels_; ++c)
            lanes[first_channel_lane() + c] = channels_catch_up_[static_cast<size_t>(c)].data();
        if (!ring_.read(at, lanes, count)) break;  // too far behind: as it is
        const float* channels[Route::kMaxChannel];
        p->process(input_from(lanes, 0, channels), incoming_pointers_.data(), count, nullptr);
        at += count;
    }
    incoming_ = p;
    fade_done_ = 0;
}

// The pipeline's input from the ring's lanes (the mono input, the summed power when there are
// several channels as their mean, the routed channels) at `offset`; `channels` holds the
// channels' pointers (one input channel: the mono input is every one of them).
PipelineInput Engine::input_from(const float* const* lanes, int offset,
                                 const float** channels) const noexcept {
    for (int c = 0; c < Route::kMaxChannel; ++c)
        channels[c] =
            routed_channels_ == 0
                ? lanes[0] + offset
                : lanes[first_channel_lane() + std::min(c, routed_channels_ - 1)] + offset;
    return {.mono = lanes[0] + offset,
            .power = summed_loudness_ ? lanes[1] + offset : nullptr,
            .channels = channels};
}

const float* Engine::downmix(const float* const* in, int offset, int count) noexcept {
    const int channels = spec_.channels;
    if (channels == 1) return in[0] + offset;
    if (input_channel_ >= 0) return in[input_channel_] + offset;
    downmix_mean(in, channels, offset, mono_.data(), count);
    return mono_.data();
}

void Engine::process(const float* const* in, float* const* out, int count) noexcept {
    const ScopedFlushDenormals no_denormals;
    apply_queued_changes();
    for (int done = 0; done < count;) {
        const int chunk = std::min(count - done, spec_.max_block);
        process_chunk(in, out, done, chunk);
        done += chunk;
    }
}

void Engine::process_chunk(const float* const* in, float* const* out, int offset,
                           int count) noexcept {
    const float* mono = downmix(in, offset, count);
    const float* power = nullptr;
    if (summed_loudness_) {  // the analysis's loudness (a replayed analysis has it)
        if (!recording_) channel_power_.process(in, offset, count, power_.data());
        power = power_.data();
    }
    const float* lanes[2 + Route::kMaxChannel] = {mono};
    if (summed_loudness_) lanes[1] = power;
    for (int c = 0; c < routed_channels_; ++c) lanes[first_channel_lane() + c] = in[c] + offset;
    ring_.write(lanes, count);
    const float* channels[Route::kMaxChannel];
    const PipelineInput input = input_from(lanes, 0, channels);
    float* outs[kMaxActuators];
    const size_t n = trims_.size();
    for (size_t k = 0; k < n; ++k) outs[k] = out[k] + offset;
    // While a new pipeline fades in, the frames are its own (primed: they go on seamlessly).
    active_->process(input, outs, count, incoming_ ? nullptr : &forwarder_);
    if (incoming_) {
        incoming_->process(input, incoming_pointers_.data(), count, &forwarder_);
        for (size_t k = 0; k < n; ++k) {
            const float* next = incoming_pointers_[k];
            for (int i = 0; i < count; ++i) {
                const float g = std::min(1.0f, static_cast<float>(fade_done_ + i) / fade_samples_);
                outs[k][i] += g * (next[i] - outs[k][i]);
            }
        }
        fade_done_ += count;
        if (fade_done_ >= fade_samples_) {
            retire(active_.release());
            active_.reset(std::exchange(incoming_, nullptr));
            latency_ = active_->latency();
            hop_samples_ = active_->hop_samples();
            if (waiting_.pipeline) start_crossfade();
        }
    }
    for (size_t k = 0; k < n; ++k) trims_[k].process(outs[k], count);
}

}  // namespace tactus
