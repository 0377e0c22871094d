#include "tactus/engine/pipeline.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/params/components.hpp"

namespace tactus {
namespace {

int64_t ceil_div(int64_t a, int64_t b) {
    return (a + b - 1) / b;
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

// What a lane's mapping reads of its listening's frames; a part route also the hits' parts.
FeatureSet lane_features(const Settings& s, const Route& route, const Overlay& overlay) {
    FeatureSet read = mapped_features(overlaid(s, overlay));
    if (route.kind == Route::Kind::parts) read = read | FeatureSet{.pitch = false};
    return read;
}

}  // namespace

void Pipeline::prepare(const ProcessSpec& spec, const Settings& settings,
                       const std::vector<ActuatorOutput>& outputs, int64_t origin_sample) {
    const double rate = spec.sample_rate_hz;
    sample_rate_hz_ = rate;
    rate_divisor_ = rate_divisor_for(rate);
    const ProcessSpec internal_spec = Upsampler::internal_spec(spec, rate_divisor_);
    const auto internal = static_cast<size_t>(internal_spec.max_block);

    // The distinct inputs heard (the mix first) and ways of playing them; outputs alike share.
    std::vector<Route> heard{Route{}};
    std::vector<const ActuatorOutput*> played;  // per lane: the first output it plays
    std::vector<size_t> lane_of(outputs.size());
    for (size_t k = 0; k < outputs.size(); ++k) {
        const ActuatorOutput& o = outputs[k];
        size_t j = 0;
        while (j < played.size() &&
               !(played[j]->route == o.route && played[j]->overlay == o.overlay))
            ++j;
        if (j == played.size()) played.push_back(&o);
        lane_of[k] = j;
        if (std::none_of(heard.begin(), heard.end(),
                         [&](const Route& r) { return r.hears_as(o.route); }))
            heard.push_back(o.route);
    }
    listenings_ = std::vector<Listening>(heard.size());
    for (size_t i = 0; i < heard.size(); ++i) {
        Listening& l = listenings_[i];
        l.route = heard[i];
        if (l.route.kind == Route::Kind::band) {
            l.band.prepare(spec, {.low_hz = l.route.low_hz, .high_hz = l.route.high_hz});
            l.heard.assign(static_cast<size_t>(spec.max_block), 0.0f);
        }
        l.analyzer.prepare(spec, settings);
    }

    // Each lane's outputs with the same profile share a chain.
    lanes_ = std::vector<Lane>(played.size());
    chain_of_.assign(outputs.size(), 0);
    first_of_chain_.clear();
    for (size_t j = 0; j < lanes_.size(); ++j) {
        Lane& lane = lanes_[j];
        lane.first_chain = first_of_chain_.size();
        for (size_t k = 0; k < outputs.size(); ++k) {
            if (lane_of[k] != j) continue;
            size_t c = lane.first_chain;
            while (c < first_of_chain_.size() &&
                   outputs[static_cast<size_t>(first_of_chain_[c])].profile != outputs[k].profile)
                ++c;
            if (c == first_of_chain_.size()) first_of_chain_.push_back(static_cast<int>(k));
            chain_of_[k] = static_cast<int>(c);
        }
        lane.chains = first_of_chain_.size() - lane.first_chain;
    }
    lane_of_.assign(lane_of.begin(), lane_of.end());
    chains_ = std::vector<ActuatorChain>(first_of_chain_.size());

    // Each lane, and its chains, with the settings its overlay makes.
    const double frames_per_second = listenings_.front().analyzer.frame_rate_hz();
    for (size_t j = 0; j < lanes_.size(); ++j) {
        Lane& lane = lanes_[j];
        lane.route = played[j]->route;
        lane.overlay = played[j]->overlay;
        const Settings own = overlaid(settings, lane.overlay);
        for (size_t c = lane.first_chain; c < lane.first_chain + lane.chains; ++c) {
            const auto& profile = outputs[static_cast<size_t>(first_of_chain_[c])].profile;
            chains_[c].prepare(spec, rate_divisor_, own, profile ? &*profile : nullptr);
        }
        lane.listening =
            static_cast<int>(std::find_if(heard.begin(), heard.end(),
                                          [&](const Route& r) { return r.hears_as(lane.route); }) -
                             heard.begin());
        lane.program = lane.route.kind == Route::Kind::all && lane.overlay.empty();
        lane.carrier.assign(internal, 0.0f);
        lane.flutter.assign(flutter_enabled(own) ? internal : 0, 0.0f);
        lane.pressure.assign(pressure_enabled(own) ? internal : 0, 0.0f);
        lane.mapper.prepare(
            own, {.frames_per_second = frames_per_second, .output_ceiling = lane_ceiling(lane)});
        lane.voice.prepare(internal_spec, own[P::post_band_high_hz]);
    }
    refer_pressures();
    program_.prepare(settings, {.frames_per_second = frames_per_second,
                                .output_ceiling = chains_.front().post().ceiling()});
    live_.prepare(settings, frames_per_second);
    update_features();
    reset();
    origin_ = position_ = origin_sample;
    replay(recording_);
}

void Pipeline::reset() noexcept {
    for (Listening& l : listenings_) {
        l.band.reset();
        l.analyzer.reset();
        l.frame_due = false;
    }
    program_.reset();
    for (Lane& lane : lanes_) {
        lane.mapper.reset();
        lane.voice.reset();
        lane.own_pulse = false;
    }
    for (auto& chain : chains_) chain.reset();
    origin_ = position_ = 0;
    replay(recording_);
}

void Pipeline::replay(const RecordedAnalysis* recording) noexcept {
    recording_ = recording;
    ran_out_ = false;
    if (!recording) return;
    const auto& frames = recording->frames;
    next_recorded_ = static_cast<size_t>(
        std::upper_bound(frames.begin(), frames.end(), position_,
                         [](int64_t at, const Features& f) { return at < f.frame_end_sample; }) -
        frames.begin());
}

// What a listening hears of the block from `offset` on.
const float* Pipeline::heard(const Listening& listening, const PipelineInput& in,
                             int offset) const {
    switch (listening.route.kind) {
        case Route::Kind::band:
            return listening.heard.data() + offset;
        case Route::Kind::channel:
            return in.channels[listening.route.channel] + offset;
        default:
            return in.mono ? in.mono + offset : nullptr;
    }
}

// The input samples up to the next frame of any listening (at most `count`), each listening
// told whether its frame is due; the mix's frames from the analysis or the recording.
int Pipeline::take_input(const PipelineInput& in, int offset, int count) noexcept {
    Listening& mix = listenings_.front();
    int chunk = count;
    if (!recording_)
        chunk = std::min(chunk, mix.analyzer.samples_to_next_frame());
    else if (next_recorded_ < recording_->frames.size())
        chunk = static_cast<int>(std::min<int64_t>(
            chunk, recording_->frames[next_recorded_].frame_end_sample - position_));
    for (size_t i = 1; i < listenings_.size(); ++i)
        chunk = std::min(chunk, listenings_[i].analyzer.samples_to_next_frame());

    if (!recording_) {
        mix.frame_due = mix.analyzer.process(heard(mix, in, offset),
                                             in.power ? in.power + offset : nullptr, chunk);
    } else if (next_recorded_ < recording_->frames.size()) {
        mix.frame_due = recording_->frames[next_recorded_].frame_end_sample - position_ == chunk;
    } else {  // ran out once a frame may have been due
        mix.frame_due = false;
        const auto shortest_hop = static_cast<int64_t>(mix.analyzer.hop_samples());
        if (position_ + chunk >= recording_->end_sample() + shortest_hop) ran_out_ = true;
    }
    for (size_t i = 1; i < listenings_.size(); ++i) {
        Listening& l = listenings_[i];
        l.frame_due = l.analyzer.process(heard(l, in, offset), nullptr, chunk);
    }
    return chunk;
}

// The features of a listening's frame due: analysed, or the mix's from the recording.
Features Pipeline::next_features(Listening& listening) noexcept {
    if (recording_ && &listening == &listenings_.front())
        return recording_->frames[next_recorded_++];
    Features features = listening.analyzer.analyse();
    features.frame_end_sample += origin_;
    features.onset_sample += origin_;
    return features;
}

void Pipeline::set_extra_features(FeatureSet features) noexcept {
    extra_features_ = features;
    update_features();
}

// Each analysis computes what its lanes' mappings read; the mix's also what the observer's
// mapping and the engine's readers read.
void Pipeline::update_features() noexcept {
    const Settings& now = live_.now();
    for (size_t i = 0; i < listenings_.size(); ++i) {
        FeatureSet read = i == 0 ? mapped_features(now) | extra_features_ : FeatureSet::none();
        for (const Lane& lane : lanes_)
            if (lane.listening == static_cast<int>(i))
                read = read | lane_features(now, lane.route, lane.overlay);
        listenings_[i].analyzer.set_features(read);
    }
}

void Pipeline::glide_flattening(const FlatteningFilter::Design& design) noexcept {
    const int glide_samples = static_cast<int>(
        ms_to_samples(spec(P::post_flatten_strength).smoothing_ms, internal_rate_hz()));
    for (auto& chain : chains_) chain.post().glide_flattening(design, glide_samples);
}

void Pipeline::apply(ControlFrame frame) noexcept {
    frame.sample = position_;
    for (Lane& lane : lanes_) lane.voice.apply(frame);
}

// The stages take the live settings as they now are, each lane with its overlay; the post
// chains at the end of the block.
void Pipeline::apply_live() noexcept {
    const Settings& s = live_.now();
    for (Listening& l : listenings_) l.analyzer.set_live(s);
    program_.set_live(s, chains_.front().post().ceiling_for(s));
    for (Lane& lane : lanes_) {
        const Settings own = overlaid(s, lane.overlay);
        lane.mapper.set_live(own, chains_[lane.first_chain].post().ceiling_for(own));
    }
    update_features();
    post_dirty_ = true;
}

// A lane plays a frame of its listening: the observer's program as it is, or its own mapping.
// A part route plays only its parts' pulses: one starts on the frame that decides its hit is one
// of them, or at least parts.route_min likely to be (parts.settle_ms after the onset; at once for
// a hit that is no drum's), and follows the frames until the next onset; other hits leave the
// pulse sounding as it was.
void Pipeline::play(int index, const Features& features, const ControlFrame& program,
                    FrameObserver* observer) noexcept {
    Lane& lane = lanes_[static_cast<size_t>(index)];
    ControlFrame control = lane.program ? program : lane.mapper.map(features);
    if (lane.route.kind == Route::Kind::parts) {
        if (features.onset) lane.own_pulse = false;
        control.trigger =
            features.part_decided &&
            (lane.route.plays(features.part) ||
             lane.route.share_of(features.part_probability) >= live_.now()[P::parts_route_min]);
        if (control.trigger) lane.own_pulse = true;
        if (!lane.own_pulse) return;
    }
    if (source_ != ProgramSource::external) lane.voice.apply(control);
    if (observer) observer->on_lane_frame(index, control);
}

// Each chain scales its lane's pressure (a fraction of the lane's first ceiling) to its own.
void Pipeline::refer_pressures() noexcept {
    for (const Lane& lane : lanes_)
        for (size_t c = lane.first_chain; c < lane.first_chain + lane.chains; ++c)
            chains_[c].set_pressure_reference(lane_ceiling(lane));
}

int Pipeline::latency() const {
    return chains_.front().latency();
}

const PostChain& Pipeline::post(int actuator) const {
    return chains_[static_cast<size_t>(chain_of_[static_cast<size_t>(actuator)])].post();
}

int64_t Pipeline::clipped_samples() const {
    int64_t clipped = 0;
    for (const auto& chain : chains_) clipped += chain.clipped_samples();
    return clipped;
}

void Pipeline::process(const PipelineInput& in, float* const* out, int count,
                       FrameObserver* observer) noexcept {
    if (live_.take_changed()) apply_live();
    for (Listening& l : listenings_)
        if (l.route.kind == Route::Kind::band) {
            std::copy_n(in.mono, count, l.heard.data());
            l.band.process(l.heard.data(), count);
        }
    const int divisor = rate_divisor_;
    int done = 0, rendered = 0;
    while (done < count) {
        const int chunk = take_input(in, done, count - done);
        // Internal sample k stands at input sample k * divisor (from the origin).
        const int64_t at = position_ - origin_;
        const auto due = static_cast<int>(ceil_div(at + chunk, divisor) - ceil_div(at, divisor));
        for (Lane& lane : lanes_)
            lane.voice.process(lane.carrier.data() + rendered,
                               lane.flutter.empty() ? nullptr : lane.flutter.data() + rendered,
                               lane.pressure.empty() ? nullptr : lane.pressure.data() + rendered,
                               due);
        rendered += due;
        position_ += chunk;
        done += chunk;
        if (std::none_of(listenings_.begin(), listenings_.end(),
                         [](const Listening& l) { return l.frame_due; }))
            continue;
        if (live_.gliding() && live_.step()) apply_live();
        for (size_t i = 0; i < listenings_.size(); ++i) {
            if (!listenings_[i].frame_due) continue;
            const Features features = next_features(listenings_[i]);
            ControlFrame program;
            if (i == 0) {
                program = program_.map(features);
                if (observer) observer->on_frame(features, program);
            }
            for (size_t j = 0; j < lanes_.size(); ++j)
                if (lanes_[j].listening == static_cast<int>(i))
                    play(static_cast<int>(j), features, program, observer);
        }
    }
    if (post_dirty_) {  // glides over an analysis frame: LiveSettings' steps join up
        const int glide = std::max(rendered, static_cast<int>(hop_samples() / divisor));
        for (const Lane& lane : lanes_) {
            const Settings own = overlaid(live_.now(), lane.overlay);
            for (size_t c = lane.first_chain; c < lane.first_chain + lane.chains; ++c)
                chains_[c].set_live(own, glide);
        }
        refer_pressures();
        post_dirty_ = false;
    }
    for (Lane& lane : lanes_) {
        float* const flutter = lane.flutter.empty() ? nullptr : lane.flutter.data();
        const float* const pressure = lane.pressure.empty() ? nullptr : lane.pressure.data();
        const size_t end = lane.first_chain + lane.chains;
        for (size_t c = lane.first_chain; c < end; ++c)
            chains_[c].process(lane.carrier.data(), flutter, pressure, rendered, c + 1 == end,
                               out[first_of_chain_[c]], count);
    }
    for (size_t k = 0; k < chain_of_.size(); ++k) {  // actuators sharing a chain: copies
        const int first = first_of_chain_[static_cast<size_t>(chain_of_[k])];
        if (first != static_cast<int>(k)) std::copy_n(out[first], count, out[k]);
    }
}

}  // namespace tactus
