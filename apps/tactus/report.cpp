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
#include "layout_option.hpp"
#include "pipeline_options.hpp"
#include "report_render.hpp"
#include "tactus/export/html_report.hpp"
#include "tactus/export/vorbis_writer.hpp"
#include "tactus/io/text_output.hpp"
#include "tactus/perception/meter.hpp"

namespace tactus::cli {
namespace {

constexpr double kMaxEmbeddedSeconds = 120;  // of sound and of vibration in the page
// The players' Vorbis quality (-0.1 ... 1): ~ 48 kb/s mono at 44.1 kHz, to listen along the
// plots, not to master from; 120 s of noise take ~ 1 MB (a 16-bit WAV: 10.6 MB).
constexpr float kPlayerQuality = 0.1f;

struct ReportOptions {
    std::string input, output, actuator, layout;
    bool force = false;
    PipelineOptions pipeline;
    BatchOptions batch;
};

std::vector<float> first_seconds(const std::vector<float>& samples, double rate, double seconds) {
    return {samples.begin(),
            samples.begin() + static_cast<ptrdiff_t>(
                                  std::min(samples.size(), static_cast<size_t>(seconds * rate)))};
}

// A layout in the summary: its name, then each output's name, route and actuator.
std::string layout_text(const Layout& layout) {
    std::string text = layout.name + ":";
    for (const LayoutOutput& o : layout.outputs)
        text += fmt::format(" {} ({}{}{})", o.name, o.output.route.text(),
                            o.actuator.empty() ? "" : ", ", o.actuator);
    return text + "; the players: the first output's";
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
    std::optional<Layout> layout;
    if (!o.layout.empty()) layout = load_layout(resolve_layout(o.layout));
    Progress progress("report");
    const ReportRender r = render_report(o.input, settings, actuator, with_progress(progress),
                                         nullptr, layout ? &*layout : nullptr);
    const double rate = r.sample_rate_hz;

    ReportData data;
    const std::string name = std::filesystem::path(o.input).filename().string();
    data.title = "tactus report: " + name;
    std::string changes;
    for (const auto& a : o.pipeline.assignments) changes += " " + a;
    data.summary = {
        {"input", fmt::format("{} ({:.2f} s at {:g} Hz)", o.input,
                              static_cast<double>(r.sound.size()) / rate, rate)},
        {"preset", o.pipeline.preset + (changes.empty() ? "" : ", --set" + changes)},
        {"actuator", layout     ? std::string("each output's own (metered through it)")
                     : actuator ? actuator->name + " (compensated, metered through it)"
                                : "none (metered through " + r.metered.front().metered_name + ")"},
        {"onsets", fmt::format("{}", r.onsets.size())},
        {"layout", layout ? layout_text(*layout) : std::string("none: one output")},
        {"tactus", TACTUS_VERSION}};
    for (const MeteredOutput& m : r.metered) {  // each output's, named with a layout
        const std::string of = m.name.empty() ? "" : m.name + ": ";
        for (const auto& c : perception::kChannels)
            data.summary.emplace_back(
                fmt::format("{}{} ({})", of, c.name, c.sensation),
                channel_text(m.summary.channels[static_cast<int>(c.channel)]));
        data.summary.emplace_back(of + "combined", channel_text(m.summary.combined));
    }
    data.onsets = r.onsets;
    data.plots = r.plots;
    data.sound_ogg =
        vorbis_file_bytes(first_seconds(r.sound, rate, kMaxEmbeddedSeconds), rate, kPlayerQuality);
    data.vibration_ogg = vorbis_file_bytes(first_seconds(r.vibration, rate, kMaxEmbeddedSeconds),
                                           rate, kPlayerQuality);
    if (static_cast<double>(r.sound.size()) / rate > kMaxEmbeddedSeconds)
        data.note = fmt::format("The players hold the first {:g} s.", kMaxEmbeddedSeconds);

    TextOutput out(output);
    out.stream() << report_html(data, dygraphs);
    out.commit();
    if (!r.unfelt_warning.empty()) note(r.unfelt_warning);
    note(fmt::format("{}: {} plots, {} onsets", output, data.plots.size(), r.onsets.size()));
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
    add_layout_option(*command, options->layout)->excludes(command->get_option("--actuator"));
    options->pipeline.add_to(*command);
    command->callback([options] { for_each_input(*options, ".report.html", report); });
}

}  // namespace tactus::cli
