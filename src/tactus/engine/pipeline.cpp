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

}  // namespace

void Pipeline::prepare(const ProcessSpec& spec, const Settings& settings,
                       const std::vector<ActuatorOutput>& outputs, int64_t origin_sample) {
    const double rate = spec.sample_rate_hz;
    sample_rate_hz_ = rate;
    rate_divisor_ = rate_divisor_for(rate);
    const ProcessSpec internal_spec = Upsampler::internal_spec(spec, rate_divisor_);
    const auto internal = static_cast<size_t>(internal_spec.max_block);
    // Actuators with the same profile share a chain.
    chains_.clear();
    chain_of_.clear();
    first_of_chain_.clear();
    for (size_t k = 0; k < outputs.size(); ++k) {
        size_t j = 0;
        while (j < k && outputs[j].profile != outputs[k].profile) ++j;
        if (j == k) {
            chains_.emplace_back().prepare(spec, rate_divisor_, settings,
                                           outputs[k].profile ? &*outputs[k].profile : nullptr);
            first_of_chain_.push_back(static_cast<int>(k));
            chain_of_.push_back(static_cast<int>(chains_.size()) - 1);
        } else {
            chain_of_.push_back(chain_of_[j]);
        }
    }
    for (auto& c : chains_) c.set_pressure_reference(chains_.front().post().ceiling());
    carrier_.assign(internal, 0.0f);
    flutter_.assign(flutter_enabled(settings) ? internal : 0, 0.0f);
    pressure_.assign(pressure_enabled(settings) ? internal : 0, 0.0f);
    analyzer_.prepare(spec, settings);
    const double frames_per_second = analyzer_.frame_rate_hz();
    mapper_.prepare(settings, {.frames_per_second = frames_per_second,
                               .output_ceiling = chains_.front().post().ceiling()});
    voice_.prepare(internal_spec, settings[P::post_band_high_hz]);
    live_.prepare(settings, frames_per_second);
    update_features();
    reset();
    origin_ = position_ = origin_sample;
    replay(recording_);
}

void Pipeline::reset() noexcept {
    analyzer_.reset();
    mapper_.reset();
    voice_.reset();
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

// The input samples up to the next frame (at most `count`), from the analysis or the recording.
int Pipeline::take_input(const float* mono, const float* power, int count,
                         bool& frame_due) noexcept {
    if (!recording_) {
        const int chunk = std::min(count, analyzer_.samples_to_next_frame());
        frame_due = analyzer_.process(mono, power, chunk);
        return chunk;
    }
    const auto& frames = recording_->frames;
    frame_due = false;
    if (next_recorded_ >= frames.size()) {  // ran out once a frame may have been due
        const auto shortest_hop = static_cast<int64_t>(analyzer_.hop_samples());
        if (position_ + count >= recording_->end_sample() + shortest_hop) ran_out_ = true;
        return count;
    }
    const int64_t to_frame = frames[next_recorded_].frame_end_sample - position_;
    if (to_frame > count) return count;
    frame_due = true;
    return static_cast<int>(to_frame);
}

// The features of the frame due: analysed, or the recording's next.
Features Pipeline::next_features() noexcept {
    if (recording_) return recording_->frames[next_recorded_++];
    Features features = analyzer_.analyse();
    features.frame_end_sample += origin_;
    features.onset_sample += origin_;
    return features;
}

void Pipeline::set_extra_features(FeatureSet features) noexcept {
    extra_features_ = features;
    update_features();
}

// The analysis computes what the mapping or the engine's readers read.
void Pipeline::update_features() noexcept {
    analyzer_.set_features(mapped_features(live_.now()) | extra_features_);
}

void Pipeline::glide_flattening(const FlatteningFilter::Design& design) noexcept {
    const int glide_samples = static_cast<int>(
        ms_to_samples(spec(P::post_flatten_strength).smoothing_ms, internal_rate_hz()));
    for (auto& chain : chains_) chain.post().glide_flattening(design, glide_samples);
}

void Pipeline::apply(ControlFrame frame) noexcept {
    frame.sample = position_;
    voice_.apply(frame);
}

// The stages take the live settings as they now are; the post chains at the end of the block.
void Pipeline::apply_live() noexcept {
    const Settings& s = live_.now();
    analyzer_.set_live(s);
    mapper_.set_live(s, chains_.front().post().ceiling_for(s));
    update_features();
    post_dirty_ = true;
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

void Pipeline::process(const float* mono, const float* power, float* const* out, int count,
                       FrameObserver* observer) noexcept {
    if (live_.take_changed()) apply_live();
    const int divisor = rate_divisor_;
    float* const flutter = flutter_.empty() ? nullptr : flutter_.data();
    float* const pressure = pressure_.empty() ? nullptr : pressure_.data();
    int done = 0, rendered = 0;
    while (done < count) {
        bool frame_due = false;
        const int chunk = take_input(mono ? mono + done : nullptr, power ? power + done : nullptr,
                                     count - done, frame_due);
        // Internal sample k stands at input sample k * divisor (from the origin).
        const int64_t at = position_ - origin_;
        const auto due = static_cast<int>(ceil_div(at + chunk, divisor) - ceil_div(at, divisor));
        voice_.process(carrier_.data() + rendered, flutter ? flutter + rendered : nullptr,
                       pressure ? pressure + rendered : nullptr, due);
        rendered += due;
        position_ += chunk;
        if (frame_due) {
            if (live_.gliding() && live_.step()) apply_live();
            const Features features = next_features();
            ControlFrame control = mapper_.map(features);
            if (source_ != ProgramSource::external) voice_.apply(control);
            if (observer) observer->on_frame(features, control);
        }
        done += chunk;
    }
    if (post_dirty_) {  // glides over an analysis frame: LiveSettings' steps join up
        const int glide = std::max(rendered, static_cast<int>(analyzer_.hop_samples() / divisor));
        for (auto& chain : chains_) chain.set_live(live_.now(), glide);
        for (auto& chain : chains_) chain.set_pressure_reference(chains_.front().post().ceiling());
        post_dirty_ = false;
    }
    for (size_t j = 0; j < chains_.size(); ++j) {
        const bool last = j + 1 == chains_.size();
        chains_[j].process(carrier_.data(), flutter, pressure, rendered, last,
                           out[first_of_chain_[j]], count);
    }
    for (size_t k = 0; k < chain_of_.size(); ++k) {  // actuators sharing a chain: copies
        const int first = first_of_chain_[static_cast<size_t>(chain_of_[k])];
        if (first != static_cast<int>(k)) std::copy_n(out[first], count, out[k]);
    }
}

}  // namespace tactus
