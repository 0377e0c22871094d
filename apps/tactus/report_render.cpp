#include "report_render.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "layout_option.hpp"
#include "meter_worker.hpp"
#include "tactus/dsp/downmix.hpp"
#include "tactus/export/haptic_track.hpp"
#include "tactus/export/thin_rows.hpp"
#include "tactus/io/actuator_file.hpp"
#include "unfelt_sound.hpp"

namespace tactus::cli {
namespace {

constexpr size_t kMaxPlotRows = 4000;  // per plot: enough for a screen, light to zoom

// Min and max of a signal per bucket, at most kMaxPlotRows buckets: the waveform plots.
std::vector<std::vector<double>> waveform_rows(const std::vector<float>& samples, double rate) {
    const size_t bucket = std::max<size_t>(1, (samples.size() + kMaxPlotRows - 1) / kMaxPlotRows);
    std::vector<std::vector<double>> out;
    for (size_t i = 0; i < samples.size(); i += bucket) {
        const auto end = std::min(samples.size(), i + bucket);
        const auto [lo, hi] = std::minmax_element(samples.begin() + static_cast<ptrdiff_t>(i),
                                                  samples.begin() + static_cast<ptrdiff_t>(end));
        out.push_back({static_cast<double>(i) / rate, *lo, *hi});
    }
    return out;
}

// At most about kMaxPlotRows, every series' extremes kept.
std::vector<std::vector<double>> thinned(const std::vector<std::vector<double>>& rows) {
    return thin_rows(rows, kMaxPlotRows);
}

ReportPlot plot(std::string id, std::string title, std::string y_label,
                std::vector<std::string> labels, std::vector<std::vector<double>> rows) {
    ReportPlot p;
    p.id = std::move(id), p.title = std::move(title), p.y_label = std::move(y_label);
    p.labels = std::move(labels), p.rows = std::move(rows);
    return p;
}

// Input analysed past a render's end, kept for renders that ring out longer (a longer decay).
constexpr double kRecordedPastEndS = 2.0;

// The engine's frames after `input` for kRecordedPastEndS of silence more, into `recording`.
void record_past_end(Engine& engine, int channels, RecordedAnalysis& recording) {
    const std::vector<float> silence(Engine::kMaxBlock, 0.0f);
    std::vector<std::vector<float>> vibration(static_cast<size_t>(engine.actuators()), silence);
    std::vector<const float*> in(static_cast<size_t>(channels), silence.data());
    std::vector<float*> out;
    out.reserve(vibration.size());
    for (auto& v : vibration) out.push_back(v.data());
    const auto total = static_cast<int64_t>(kRecordedPastEndS * engine.sample_rate_hz());
    for (int64_t done = 0; done < total; done += Engine::kMaxBlock) {
        engine.process(in.data(), out.data(), Engine::kMaxBlock);
        for (AnalysisFrame f; engine.pop_frame(f);) recording.frames.push_back(f.features);
    }
}

// One render, playing `replayed` back or (null) analysing the file into `recording` (if given).
ReportRender render_once(const std::string& input, const Settings& settings,
                         const std::optional<ActuatorProfile>& actuator,
                         const RunCallbacks& callbacks,
                         std::shared_ptr<const RecordedAnalysis> replayed,
                         RecordedAnalysis* recording, const Layout* layout) {
    const std::vector<ActuatorOutput> outputs =
        layout ? layout_outputs(*layout, settings)
               : std::vector<ActuatorOutput>{ActuatorOutput{.profile = actuator}};
    // Each output metered through its own profile, else the default actuator.
    const size_t n = outputs.size();
    std::optional<ActuatorProfile> default_actuator;
    std::vector<ActuatorProfile> metered(n);
    for (size_t k = 0; k < n; ++k) {
        if (!outputs[k].profile && !default_actuator)
            default_actuator = load_actuator(resolve_actuator(kDefaultActuator));
        metered[k] = outputs[k].profile ? *outputs[k].profile : *default_actuator;
    }
    ReportRender out;
    out.metered.resize(n);
    Engine engine(settings);
    engine.set_actuators(outputs);
    out.analysis_replayed = replayed != nullptr;
    engine.replay_analysis(std::move(replayed));
    std::vector<perception::MeterSummariser> summarisers(n);
    std::vector<std::vector<std::vector<double>>> levels(n);
    std::vector<std::vector<double>> features, program;
    std::vector<std::vector<float>> drives(n);  // each output's; the first becomes `vibration`
    // From the first block, when the rate is known; gone before what their readings go to.
    std::deque<MeterWorker> meters;  // each holds a thread: never moved
    const AlignedSink sink = [&](const float* const* audio, int audio_channels,
                                 const float* const* vib, int, int frames) {
        for (size_t k = meters.size(); k < n; ++k)
            meters.emplace_back(
                engine.sample_rate_hz(), metered[k], settings[P::perception_contact_area_cm2],
                [&, k](const perception::MeterReading& r) {
                    summarisers[k].add(r);
                    levels[k].push_back({r.time_s, r.level_db[0], r.level_db[1], r.level_db[2],
                                         r.level_db[3], r.combined_db});
                });
        const size_t at = out.sound.size();
        out.sound.resize(at + static_cast<size_t>(frames));
        downmix_mean(audio, audio_channels, 0, out.sound.data() + at, frames);  // as heard
        for (size_t k = 0; k < n; ++k) {
            drives[k].insert(drives[k].end(), vib[k], vib[k] + frames);
            meters[k].write(vib[k], frames);
        }
    };
    UnfeltSound unfelt(settings);
    int channels = 0;
    RunCallbacks run = callbacks;
    run.on_start = [&](double rate, int input_channels) {
        channels = input_channels;
        if (callbacks.on_start) callbacks.on_start(rate, input_channels);
    };
    run.on_output = [&](const float* const* v, int frames) {
        unfelt.on_output(v, engine.actuators(), frames);
    };
    const FrameSink on_frame = [&](const AnalysisFrame& f) {
        if (recording) recording->frames.push_back(f.features);
        unfelt.on_loudness(f.features.loudness_db);
        const double t = static_cast<double>(f.features.frame_end_sample) / engine.sample_rate_hz();
        const bool pitched = f.features.pitch_confidence > 0 && f.features.pitch_hz > 0;
        features.push_back({t, f.features.loudness_db, f.features.brightness_hz,
                            f.features.noisiness, pitched ? f.features.pitch_hz : NAN});
        program.push_back({t, f.control.frequency_hz, f.control.amplitude});
    };
    const std::vector<HapticTrack> tracks =
        render_haptic_tracks(input, engine, sink, run, on_frame);
    if (out.analysis_replayed && engine.replay_ran_out()) {  // the caller renders again
        out.analysis_replayed = false;
        return out;
    }
    if (recording) record_past_end(engine, channels, *recording);
    out.unfelt_warning = unfelt.warning(input, engine.sample_rate_hz());
    for (MeterWorker& meter : meters) meter.finish();  // each worker's readings are all in
    meters.clear();
    out.sample_rate_hz = engine.sample_rate_hz();
    out.latency_frames = engine.latency();
    const double rate = out.sample_rate_hz;
    // The meters' last readings cover their windows past the end: the plots stop at the end.
    const double end_s = static_cast<double>(out.sound.size()) / rate;
    for (size_t k = 0; k < n; ++k) {
        out.metered[k] = {.name = layout ? layout->outputs[k].name : std::string(),
                          .metered_name = metered[k].name,
                          .summary = summarisers[k].summary()};
        std::erase_if(levels[k], [&](const std::vector<double>& r) { return r[0] > end_s; });
    }
    // The onsets the outputs play: those of an output on `all` (every onset), else every
    // output's, each time once.
    const auto all = std::find_if(outputs.begin(), outputs.end(), [](const ActuatorOutput& o) {
        return o.route.kind == Route::Kind::all;
    });
    for (size_t k = 0; k < tracks.size(); ++k)
        if (all == outputs.end() || k == static_cast<size_t>(all - outputs.begin()))
            for (const auto& onset : tracks[k].onsets)
                out.onsets.push_back({onset.time_s, onset.part});
    std::sort(out.onsets.begin(), out.onsets.end(),
              [](const ReportOnset& a, const ReportOnset& b) { return a.time_s < b.time_s; });
    out.onsets.erase(std::unique(out.onsets.begin(), out.onsets.end(),
                                 [](const ReportOnset& a, const ReportOnset& b) {
                                     return b.time_s - a.time_s < HapticTrack::kStepS;
                                 }),
                     out.onsets.end());

    // Each output's felt envelope on one scale: 1 is the loudest output's peak.
    double full_scale = 0;
    for (const HapticTrack& t : tracks) full_scale = std::max(full_scale, t.felt_full_scale);
    std::vector<std::string> felt_labels{"felt"};
    if (layout) {
        felt_labels.clear();
        for (const LayoutOutput& o : layout->outputs) felt_labels.push_back(o.name);
    }
    std::vector<std::vector<double>> felt(tracks.front().intensity.size());
    for (size_t i = 0; i < felt.size(); ++i) {
        felt[i].push_back(static_cast<double>(i) * HapticTrack::kStepS);
        for (const HapticTrack& t : tracks)
            felt[i].push_back(i < t.intensity.size() && full_scale > 0
                                  ? t.intensity[i] * t.felt_full_scale / full_scale
                                  : 0.0);
    }
    const auto column = [&](size_t c) {
        std::vector<std::vector<double>> rows;
        rows.reserve(features.size());
        for (const auto& f : features) rows.push_back({f[0], f[c]});
        return thinned(rows);
    };
    ReportPlot waveform = plot("waveform", "Sound, with its onsets", "full scale", {"sound"},
                               waveform_rows(out.sound, rate));
    waveform.onsets = waveform.band = true;
    ReportPlot loudness = plot("loudness", "Loudness", "dB LKFS", {"loudness_db"}, column(1));
    loudness.onsets = true;
    ReportPlot brightness =
        plot("brightness", "Brightness (spectral centroid)", "Hz", {"brightness_hz"}, column(2));
    brightness.log_y = true;
    ReportPlot pitch = plot("pitch", "Pitch (where found)", "Hz", {"pitch_hz"}, column(4));
    pitch.log_y = pitch.points = true;
    ReportPlot vibration_program = plot("program", "Vibration program: frequency and amplitude",
                                        "Hz", {"frequency_hz", "amplitude"}, thinned(program));
    vibration_program.right_axis = {"amplitude"};
    ReportPlot felt_plot = plot("felt",
                                layout ? "Felt envelope of each output (P-weighted; 1: the loudest "
                                         "output's peak)"
                                       : "Felt envelope (P-weighted; 1: its peak)",
                                "0 ... 1", felt_labels, thinned(felt));
    felt_plot.onsets = true;
    out.plots = {waveform,
                 loudness,
                 brightness,
                 plot("noisiness", "Noisiness (spectral flatness: 0 tonal, 1 noise)", "flatness",
                      {"noisiness"}, column(3)),
                 pitch,
                 vibration_program};
    // Each output's drive; then the felt envelopes together; then each output's sensation.
    const auto suffix = [&](size_t k) { return layout ? "-" + out.metered[k].name : ""; };
    for (size_t k = 0; k < n; ++k) {
        ReportPlot drive =
            plot("vibration" + suffix(k),
                 layout ? "Vibration of " + out.metered[k].name + " (its actuator's drive)"
                        : "Vibration (the actuator's drive)",
                 "full scale", {"vibration"}, waveform_rows(drives[k], rate));
        drive.onsets = drive.band = true;
        out.plots.push_back(std::move(drive));
    }
    out.plots.push_back(felt_plot);
    for (size_t k = 0; k < n; ++k)
        out.plots.push_back(plot("sensation" + suffix(k),
                                 "Sensation level per channel of touch" +
                                     (layout ? ": " + out.metered[k].name : std::string()) +
                                     " (through " + out.metered[k].metered_name + ")",
                                 "dB SL", {"P", "NPI", "NPII", "NPIII", "combined"},
                                 thinned(levels[k])));
    out.vibration = std::move(drives.front());
    return out;
}

}  // namespace

ReportRender render_report(const std::string& input, const Settings& settings,
                           const std::optional<ActuatorProfile>& actuator,
                           const RunCallbacks& callbacks, AnalysisCache* analyses,
                           const Layout* layout) {
    if (!analyses)
        return render_once(input, settings, actuator, callbacks, nullptr, nullptr, layout);
    const std::string key = AnalysisCache::key_of(input, settings);
    if (auto kept = analyses->find(key)) {
        ReportRender out = render_once(input, settings, actuator, callbacks, kept, nullptr, layout);
        if (out.analysis_replayed) return out;
    }
    auto recording = std::make_shared<RecordedAnalysis>();
    ReportRender out =
        render_once(input, settings, actuator, callbacks, nullptr, recording.get(), layout);
    analyses->keep(key, std::move(recording));
    return out;
}

}  // namespace tactus::cli
