// tactus report IN [-o report.html]: one self-contained HTML page to look at what tactus makes of
// a sound (export/html_report.hpp): the waveform with its onsets, loudness, brightness,
// noisiness and pitch, the vibration's frequency and amplitude, its waveform and felt envelope,
// the sensation level per channel of touch, and a summary (preset, actuator, onsets, the
// meter's figures); the sound and the vibration playable from the page.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <optional>

#include "actuator_option.hpp"
#include "batch_plan.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "global_options.hpp"
#include "pipeline_options.hpp"
#include "tactus/actuator/drive_meter.hpp"
#include "tactus/dsp/downmix.hpp"
#include "tactus/export/haptic_track.hpp"
#include "tactus/export/html_report.hpp"
#include "tactus/export/thin_rows.hpp"
#include "tactus/export/vorbis_writer.hpp"
#include "tactus/io/text_output.hpp"
#include "tactus/perception/meter.hpp"

namespace tactus::cli {
namespace {

constexpr size_t kMaxPlotRows = 4000;        // per plot: enough for a screen, light to zoom
constexpr double kMaxEmbeddedSeconds = 120;  // of sound and of vibration in the page
// The players' Vorbis quality (-0.1 ... 1): ~ 48 kb/s mono at 44.1 kHz, to listen along the
// plots, not to master from; 120 s of noise take ~ 1 MB (a 16-bit WAV: 10.6 MB).
constexpr float kPlayerQuality = 0.1f;

struct ReportOptions {
    std::string input, output, actuator;
    bool force = false;
    PipelineOptions pipeline;
    BatchOptions batch;
};

// Min and max of a signal per bucket, at most kMaxPlotRows buckets: the waveform plots.
class Waveform {
  public:
    explicit Waveform(double sample_rate_hz) : rate_(sample_rate_hz) {}
    void add(float x) { samples_.push_back(x); }
    std::vector<std::vector<double>> rows() const {
        const size_t bucket =
            std::max<size_t>(1, (samples_.size() + kMaxPlotRows - 1) / kMaxPlotRows);
        std::vector<std::vector<double>> out;
        for (size_t i = 0; i < samples_.size(); i += bucket) {
            const auto end = std::min(samples_.size(), i + bucket);
            const auto [lo, hi] = std::minmax_element(samples_.begin() + i, samples_.begin() + end);
            out.push_back({static_cast<double>(i) / rate_, *lo, *hi});
        }
        return out;
    }
    std::vector<float> first_seconds(double seconds) const {
        return {samples_.begin(),
                samples_.begin() + std::min(samples_.size(), static_cast<size_t>(seconds * rate_))};
    }
    size_t size() const { return samples_.size(); }

  private:
    double rate_;
    std::vector<float> samples_;
};

// At most about kMaxPlotRows, every series' extremes kept.
std::vector<std::vector<double>> thinned(const std::vector<std::vector<double>>& rows) {
    return thin_rows(rows, kMaxPlotRows);
}

std::string channel_text(const perception::ChannelSummary& c) {
    if (c.engaged_fraction <= 0) return fmt::format("max {:.1f} dB SL, not engaged", c.max_db);
    return fmt::format("max {:.1f} dB SL, engaged {:.1f} % of the time, median {:.1f} dB SL",
                       c.max_db, 100 * c.engaged_fraction, c.median_engaged_db);
}

void report(const ReportOptions& o) {
    const Settings settings = o.pipeline.resolve();
    const std::string output = o.output.empty()
                                   ? std::filesystem::path(o.input).stem().string() + ".report.html"
                                   : o.output;
    if (!is_stdout(output)) check_output(o.input, output, o.force);
    const Dygraphs dygraphs = load_dygraphs();  // before any audio: a missing package says so
    std::optional<ActuatorProfile> actuator;
    if (!o.actuator.empty()) actuator = load_actuator_for(o.actuator, settings);
    const ActuatorProfile metered =
        actuator ? *actuator : load_actuator(resolve_actuator(kDefaultActuator));

    Engine engine(settings);
    engine.set_actuator(actuator);
    std::optional<Waveform> sound, vibration;
    DriveMeter meter;
    perception::MeterSummariser summariser;
    std::vector<std::vector<double>> features, program, levels;
    const auto on_reading = [&](const perception::MeterReading& r) {
        summariser.add(r);
        levels.push_back(
            {r.time_s, r.level_db[0], r.level_db[1], r.level_db[2], r.level_db[3], r.combined_db});
    };
    std::vector<float> mono;
    const AlignedSink sink = [&](const float* const* audio, int audio_channels,
                                 const float* const* vib, int, int frames) {
        if (!sound) {
            sound.emplace(engine.sample_rate_hz());
            vibration.emplace(engine.sample_rate_hz());
            meter.prepare(engine.sample_rate_hz(), metered,
                          settings[P::perception_contact_area_cm2]);
        }
        mono.resize(static_cast<size_t>(frames));
        downmix_mean(audio, audio_channels, 0, mono.data(), frames);  // as the engine hears it
        for (int i = 0; i < frames; ++i) {
            sound->add(mono[i]);
            vibration->add(vib[0][i]);
        }
        meter.write(vib[0], frames, on_reading);
    };
    const FrameSink on_frame = [&](const AnalysisFrame& f) {
        const double t = static_cast<double>(f.features.frame_end_sample) / engine.sample_rate_hz();
        const bool pitched = f.features.pitch_confidence > 0 && f.features.pitch_hz > 0;
        features.push_back({t, f.features.loudness_db, f.features.brightness_hz,
                            f.features.noisiness, pitched ? f.features.pitch_hz : NAN});
        program.push_back({t, f.control.frequency_hz, f.control.amplitude});
    };
    Progress progress("report");
    HapticTrack track =
        render_haptic_track(o.input, engine, sink, with_progress(progress), on_frame);
    meter.finish(on_reading);
    const perception::MeterSummary summary = summariser.summary();
    const double rate = engine.sample_rate_hz();
    // The meter's last readings cover its windows past the end: the plots stop at the end.
    const double end_s = static_cast<double>(sound->size()) / rate;
    std::erase_if(levels, [&](const std::vector<double>& r) { return r[0] > end_s; });

    ReportData data;
    const std::string name = std::filesystem::path(o.input).filename().string();
    data.title = "tactus report: " + name;
    std::string changes;
    for (const auto& a : o.pipeline.assignments) changes += " " + a;
    data.summary = {{"input", fmt::format("{} ({:.2f} s at {:g} Hz)", o.input,
                                          static_cast<double>(sound->size()) / rate, rate)},
                    {"preset", o.pipeline.preset + (changes.empty() ? "" : ", --set" + changes)},
                    {"actuator", actuator ? actuator->name + " (compensated, metered through it)"
                                          : "none (metered through " + metered.name + ")"},
                    {"onsets", fmt::format("{}", track.onsets.size())},
                    {"tactus", TACTUS_VERSION}};
    for (const auto& c : perception::kChannels)
        data.summary.emplace_back(fmt::format("{} ({})", c.name, c.sensation),
                                  channel_text(summary.channels[static_cast<int>(c.channel)]));
    data.summary.emplace_back("combined", channel_text(summary.combined));
    for (const auto& onset : track.onsets) data.onsets.push_back({onset.time_s, onset.part});

    std::vector<std::vector<double>> felt;
    for (size_t i = 0; i < track.intensity.size(); ++i)
        felt.push_back({static_cast<double>(i) * HapticTrack::kStepS, track.intensity[i]});
    const auto column = [&](size_t c) {
        std::vector<std::vector<double>> rows;
        for (const auto& f : features) rows.push_back({f[0], f[c]});
        return thinned(rows);
    };
    const auto plot = [](std::string id, std::string title, std::string y_label,
                         std::vector<std::string> labels, std::vector<std::vector<double>> rows) {
        ReportPlot p;
        p.id = std::move(id), p.title = std::move(title), p.y_label = std::move(y_label);
        p.labels = std::move(labels), p.rows = std::move(rows);
        return p;
    };
    ReportPlot waveform =
        plot("waveform", "Sound, with its onsets", "full scale", {"sound"}, sound->rows());
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
    ReportPlot drive = plot("vibration", "Vibration (the actuator's drive)", "full scale",
                            {"vibration"}, vibration->rows());
    drive.onsets = drive.band = true;
    ReportPlot felt_plot =
        plot("felt", "Felt envelope (P-weighted; 1: its peak)", "0 ... 1", {"felt"}, thinned(felt));
    felt_plot.onsets = true;
    data.plots = {
        waveform,
        loudness,
        brightness,
        plot("noisiness", "Noisiness (spectral flatness: 0 tonal, 1 noise)", "flatness",
             {"noisiness"}, column(3)),
        pitch,
        vibration_program,
        drive,
        felt_plot,
        plot("sensation", "Sensation level per channel of touch (through " + metered.name + ")",
             "dB SL", {"P", "NPI", "NPII", "NPIII", "combined"}, thinned(levels))};
    data.sound_ogg =
        vorbis_file_bytes(sound->first_seconds(kMaxEmbeddedSeconds), rate, kPlayerQuality);
    data.vibration_ogg =
        vorbis_file_bytes(vibration->first_seconds(kMaxEmbeddedSeconds), rate, kPlayerQuality);
    if (static_cast<double>(sound->size()) / rate > kMaxEmbeddedSeconds)
        data.note = fmt::format("The players hold the first {:g} s.", kMaxEmbeddedSeconds);

    TextOutput out(output);
    out.stream() << report_html(data, dygraphs);
    out.commit();
    note(fmt::format("{}: {} plots, {} onsets", output, data.plots.size(), track.onsets.size()));
}

}  // namespace

void add_report(CLI::App& app) {
    auto options = std::make_shared<ReportOptions>();
    CLI::App* command = app.add_subcommand(
        "report", "write one self-contained HTML page of plots, figures and players");
    options->batch.add_to(*command,
                          "report.html, one input (default: <input name>.report.html; - for "
                          "stdout)",
                          ".report.html");
    add_actuator_option(*command, options->actuator,
                        "actuator profile (name or FILE.toml): render for it and meter through it "
                        "(default: none, metered through voice-coil)");
    options->pipeline.add_to(*command);
    command->callback([options] { for_each_input(*options, ".report.html", report); });
}

}  // namespace tactus::cli
