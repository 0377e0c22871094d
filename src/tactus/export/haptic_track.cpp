#include "tactus/export/haptic_track.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>

#include "tactus/dsp/delay_line.hpp"
#include "tactus/export/felt_envelope.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/perception/threshold.hpp"

namespace tactus {
namespace {

// An onset's intensity is its pulse's felt peak within this time of it.
constexpr double kOnsetPeakWindowS = 0.03;
// A lane's pulse starts this long after its onset at most (a part route's, once decided).
constexpr double kLanePulseMatchS = 0.1;

// The carrier in effect at each input sample, from the ControlFrames in order.
class CarrierTrack {
  public:
    void add(int64_t sample, double frequency_hz) { changes_.push_back({sample, frequency_hz}); }
    // The carrier at `sample` (samples asked for in increasing order).
    double at(int64_t sample) {
        while (!changes_.empty() && changes_.front().first <= sample) {
            current_ = changes_.front().second;
            changes_.pop_front();
        }
        return current_;
    }

  private:
    std::deque<std::pair<int64_t, double>> changes_;
    double current_ = 0;
};

}  // namespace

double HapticTrack::intensity_at(double time_s) const {
    if (intensity.empty()) return 0;
    const double x = std::clamp(time_s / kStepS, 0.0, static_cast<double>(intensity.size() - 1));
    const auto i = static_cast<size_t>(x);
    if (i + 1 >= intensity.size()) return intensity.back();
    return intensity[i] + (x - static_cast<double>(i)) * (intensity[i + 1] - intensity[i]);
}

double sharpness_of(double frequency_hz) {
    using perception::kPHighEdgeHz, perception::kPLowEdgeHz;
    if (frequency_hz <= 0) return 0;
    return std::clamp(std::log(frequency_hz / kPLowEdgeHz) / std::log(kPHighEdgeHz / kPLowEdgeHz),
                      0.0, 1.0);
}

std::vector<HapticTrack> render_haptic_tracks(const std::filesystem::path& input, Engine& engine,
                                              const AlignedSink& sink,
                                              const RunCallbacks& callbacks,
                                              const FrameSink& frames, RunAnalysis analysis) {
    engine.enable_frame_queue();
    const std::vector<ActuatorOutput> routed = engine.outputs();
    const size_t outputs = routed.size();
    // An output on `all` without an overlay plays the program as it is; the others their lane's.
    std::vector<bool> plays_program(outputs);
    for (size_t k = 0; k < outputs; ++k)
        plays_program[k] = routed[k].route.kind == Route::Kind::all && routed[k].overlay.empty();
    std::vector<FeltEnvelope> envelopes;  // per output
    CarrierTrack carrier;                 // the program's
    std::vector<CarrierTrack> lane_carriers;
    std::vector<double> lane_hz;
    std::vector<int> lane_of(outputs);
    // Each pulse a lane starts: (sample, carrier).
    std::vector<std::vector<std::pair<int64_t, double>>> lane_pulses;
    // Each onset with the carrier when its part was decided (or, undecided, on its own frame).
    std::vector<std::pair<DecidedOnset, double>> onsets;
    OnsetDecisions decisions;
    double onset_carrier_hz = 0;  // the carrier on the frame of the onset waiting for its part
    int audio_channels = 0;
    int64_t latency = 0, skipped = 0, aligned = 0;
    DelayLine audio_delay;  // the input, by the latency: in step with the vibration
    std::vector<std::vector<float>> audio_block;
    std::vector<float*> audio_out;
    // The input (the tail's silence included) delayed into audio_block.
    const auto delay_audio = [&](const float* const* in, int frames) {
        for (int c = 0; c < audio_channels; ++c) {
            if (audio_block[c].size() < static_cast<size_t>(frames))
                audio_block[c].resize(static_cast<size_t>(frames));
            audio_out[c] = audio_block[c].data();
        }
        audio_delay.process(in, audio_out.data(), frames);
    };

    const auto take_frames = [&] {
        for (AnalysisFrame frame; engine.pop_frame(frame);) {
            if (frames) frames(frame);
            carrier.add(frame.control.sample, frame.control.frequency_hz);
            decisions.add(frame.features, [&](const DecidedOnset& onset) {
                onsets.emplace_back(
                    onset, onset.part_decided ? frame.control.frequency_hz : onset_carrier_hz);
            });
            if (frame.features.onset) onset_carrier_hz = frame.control.frequency_hz;
        }
        for (LaneFrame frame; engine.pop_lane_frame(frame);) {
            const auto lane = static_cast<size_t>(frame.lane);
            lane_carriers[lane].add(frame.control.sample, frame.control.frequency_hz);
            if (frame.control.trigger)
                lane_pulses[lane].emplace_back(frame.control.sample, frame.control.frequency_hz);
        }
    };
    // Vibration sample k (after the latency) lines up with input sample k.
    const auto on_output = [&](const float* const* vibration, int frames) {
        take_frames();
        if (callbacks.on_output) callbacks.on_output(vibration, frames);
        const int skip = static_cast<int>(std::min<int64_t>(frames, latency - skipped));
        skipped += skip;
        const int count = frames - skip;
        if (count <= 0) return;
        // The carrier changes at hop boundaries at most; the envelopes take it per hop.
        for (int done = 0; done < count;) {
            const int64_t at = aligned + done;
            const int chunk =
                std::min(count - done, std::max(1, static_cast<int>(engine.hop_samples())));
            const double program_hz = carrier.at(at);
            for (size_t l = 0; l < lane_carriers.size(); ++l) lane_hz[l] = lane_carriers[l].at(at);
            for (size_t k = 0; k < outputs; ++k)
                envelopes[k].write(
                    vibration[k] + skip + done, chunk,
                    plays_program[k] ? program_hz : lane_hz[static_cast<size_t>(lane_of[k])]);
            done += chunk;
        }
        if (sink) {
            std::vector<const float*> a(audio_channels), v(engine.actuators());
            for (int c = 0; c < audio_channels; ++c) a[c] = audio_block[c].data() + skip;
            for (int c = 0; c < engine.actuators(); ++c) v[c] = vibration[c] + skip;
            sink(a.data(), audio_channels, v.data(), engine.actuators(), count);
        }
        aligned += count;
    };
    RunCallbacks run = callbacks;
    run.on_start = [&](double sample_rate_hz, int channels) {
        envelopes.assign(outputs, FeltEnvelope(sample_rate_hz));
        int lanes = 0;
        for (size_t k = 0; k < outputs; ++k) {
            lane_of[k] = engine.lane_of(static_cast<int>(k));
            lanes = std::max(lanes, lane_of[k] + 1);
        }
        lane_carriers.assign(static_cast<size_t>(lanes), {});
        lane_hz.assign(static_cast<size_t>(lanes), 0.0);
        lane_pulses.assign(static_cast<size_t>(lanes), {});
        audio_channels = channels;
        latency = engine.latency();
        audio_block.assign(audio_channels, {});
        audio_out.resize(audio_channels);
        if (sink)
            audio_delay.prepare(audio_channels, static_cast<int>(latency),
                                static_cast<int>(latency));
        if (callbacks.on_start) callbacks.on_start(sample_rate_hz, channels);
    };
    if (sink) run.on_input = delay_audio;
    run.on_output = on_output;
    const RunSummary summary = run_file(input, engine, run, RunTail::ring_out, analysis);
    take_frames();
    decisions.finish(
        [&](const DecidedOnset& onset) { onsets.emplace_back(onset, onset_carrier_hz); });

    std::vector<HapticTrack> tracks(outputs);
    for (size_t k = 0; k < outputs; ++k) {
        HapticTrack& track = tracks[k];
        const std::vector<double> felt = envelopes[k].felt();
        track.felt_full_scale = felt.empty() ? 0.0 : *std::max_element(felt.begin(), felt.end());
        track.intensity.resize(felt.size());
        track.sharpness.resize(felt.size());
        for (size_t i = 0; i < felt.size(); ++i) {
            track.intensity[i] = track.felt_full_scale > 0 ? felt[i] / track.felt_full_scale : 0.0;
            track.sharpness[i] = sharpness_of(envelopes[k].carrier_hz()[i]);
        }
        // Its onsets: the mix's that its route plays (each with the carrier of the pulse its lane
        // started for it, when there is one); a band's or a channel's own, its lane's pulses.
        const Route& route = routed[k].route;
        const auto& pulses = lane_pulses[static_cast<size_t>(lane_of[k])];
        const auto add_onset = [&](int64_t sample, double frequency_hz, DrumPart part,
                                   double strength_db) {
            const double time_s = static_cast<double>(sample) / summary.sample_rate_hz;
            const auto first = static_cast<size_t>(std::max(0.0, time_s / HapticTrack::kStepS));
            const size_t last =
                std::min(track.intensity.size(),
                         first + static_cast<size_t>(kOnsetPeakWindowS / HapticTrack::kStepS));
            double peak = 0;
            for (size_t i = first; i < last; ++i) peak = std::max(peak, track.intensity[i]);
            track.onsets.push_back({.time_s = time_s,
                                    .intensity = peak,
                                    .sharpness = sharpness_of(frequency_hz),
                                    .part = part,
                                    .strength_db = strength_db});
        };
        if (route.own_analysis()) {
            for (const auto& [sample, frequency_hz] : pulses)
                add_onset(sample, frequency_hz, DrumPart::other, HapticOnset{}.strength_db);
            continue;
        }
        for (const auto& [onset, frequency_hz] : onsets) {
            if (!route.plays(onset.part)) continue;
            double pulse_hz = frequency_hz;
            if (!plays_program[k]) {  // the lane's pulse for it, started at or after it
                const auto pulse = std::lower_bound(pulses.begin(), pulses.end(),
                                                    std::pair{onset.onset_sample, 0.0});
                if (pulse != pulses.end() &&
                    pulse->first - onset.onset_sample < kLanePulseMatchS * summary.sample_rate_hz)
                    pulse_hz = pulse->second;
            }
            add_onset(onset.onset_sample, pulse_hz, onset.part, onset.strength_db);
        }
    }
    return tracks;
}

std::vector<Breakpoint> simplify(const std::vector<double>& values, double step_s,
                                 double tolerance) {
    const size_t n = values.size();
    if (n == 0) return {};
    if (n == 1) return {{0.0, values[0]}};
    std::vector<bool> keep(n, false);
    keep[0] = keep[n - 1] = true;
    std::vector<std::pair<size_t, size_t>> spans{{0, n - 1}};
    while (!spans.empty()) {
        const auto [a, b] = spans.back();
        spans.pop_back();
        double worst = -1;
        size_t at = a;
        for (size_t i = a + 1; i < b; ++i) {
            const double line = values[a] + (values[b] - values[a]) * static_cast<double>(i - a) /
                                                static_cast<double>(b - a);
            if (const double d = std::abs(values[i] - line); d > worst) {
                worst = d;
                at = i;
            }
        }
        if (worst > tolerance) {
            keep[at] = true;
            spans.push_back({a, at});
            spans.push_back({at, b});
        }
    }
    std::vector<Breakpoint> points;
    for (size_t i = 0; i < n; ++i)
        if (keep[i]) points.push_back({static_cast<double>(i) * step_s, values[i]});
    return points;
}

}  // namespace tactus
