// tactus meter FILE [--actuator NAME] [--contact-area CM2] [-o FILE.csv]: which channels of
// touch a vibration file engages through an actuator, and how strongly (dB SL over time). The
// file is the actuator's drive, metered through its model (actuator/drive_meter.hpp): the
// channels' mean, or for a file rendered with a layout each output's channel through its own
// actuator, named by the output.
#include "tactus/perception/meter.hpp"

#include <fmt/format.h>

#include <iostream>
#include <sstream>

#include "actuator_option.hpp"
#include "batch_plan.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "global_options.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/layout_file.hpp"
#include "tactus/io/meter_run.hpp"
#include "tactus/io/render_info.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus::cli {
namespace {

using perception::kChannels;

struct MeterOptions {
    std::string input, output, actuator;  // empty: the one the file was rendered for
    bool force = false;
    BatchOptions batch;
    double contact_area_cm2 = Settings()[P::perception_contact_area_cm2];
};

// One vibration metered, with what names it in the summary and the CSV's columns.
struct Metered {
    MeteredChannel what{};
    std::string name{};  // empty: the file's one vibration
    perception::MeterSummariser summariser{};
    std::vector<perception::MeterReading> readings{};  // for the CSV
};

void print_summary(std::ostream& out, const MeterOptions& o, const Metered& m, double seconds) {
    const ActuatorProfile& a = m.what.actuator;
    out << fmt::format(
        "{}{}: {:.2f} s through {} ({}, {:g} um at {:g} Hz full scale, {}), contact {:g} cm2\n",
        o.input,
        m.name.empty() ? std::string()
                       : fmt::format(" output {} (channel {})", m.name, m.what.channel + 1),
        seconds, a.name, type_name(a.type), a.displacement_um, a.reference_hz,
        a.dc ? "DC capable" : "no DC", o.contact_area_cm2);
    out << fmt::format("{:<9}{:<11}{:>10}{:>11}{:>14}\n", "channel", "sensation", "max_dB_SL",
                       "engaged_%", "median_dB_SL");
    const auto row = [&out](std::string_view name, std::string_view sensation,
                            const perception::ChannelSummary& c) {
        out << fmt::format("{:<9}{:<11}{:>10.1f}{:>11.1f}{:>14}\n", name, sensation, c.max_db,
                           100 * c.engaged_fraction,
                           c.engaged_fraction > 0 ? fmt::format("{:.1f}", c.median_engaged_db)
                                                  : std::string("not engaged"));
    };
    const perception::MeterSummary s = m.summariser.summary();
    for (const auto& c : kChannels)
        row(c.name, c.sensation, s.channels[static_cast<int>(c.channel)]);
    row("combined", "", s.combined);
}

// What the file holds: a layout's outputs (its comment names the layout), each through its own
// actuator (--actuator: all through that one); else the channels' mean.
std::vector<Metered> metered_of(const MeterOptions& o) {
    const RenderInfo info = RenderInfo::from_comment(AudioReader(o.input).comment());
    std::vector<Metered> metered;
    if (!info.layout.empty()) {
        Layout layout;
        try {
            layout = load_layout(resolve_layout(info.layout));
        } catch (const std::exception& e) {
            note(fmt::format("{}: rendered with layout {}, not found ({}): the channels' mean",
                             o.input, info.layout, e.what()));
        }
        for (const LayoutOutput& output : layout.outputs) {
            const std::string actuator = !o.actuator.empty()        ? o.actuator
                                         : !output.actuator.empty() ? output.actuator
                                                                    : std::string("voice-coil");
            metered.push_back({.what = {.channel = output.channel,
                                        .actuator = load_actuator(resolve_actuator(actuator))},
                               .name = output.name});
        }
    }
    if (metered.empty())
        metered.push_back(
            {.what = {.channel = -1,
                      .actuator = actuator_of_vibration(o.actuator, o.input, "metered")}});
    return metered;
}

void meter(const MeterOptions& o) {
    if (!is_stdout(o.output)) check_output(o.input, o.output, o.force);
    std::vector<Metered> metered = metered_of(o);
    std::vector<MeteredChannel> channels(metered.size());
    for (size_t k = 0; k < metered.size(); ++k) channels[k] = metered[k].what;
    Progress progress("meter");
    FileSource vibration(o.input, kStreamBlockFrames);
    const RunSummary run = meter_source(
        vibration, channels, o.contact_area_cm2,
        [&](size_t k, const perception::MeterReading& r) {
            metered[k].summariser.add(r);
            if (!o.output.empty()) metered[k].readings.push_back(r);
        },
        with_progress(progress));
    if (!o.output.empty()) {
        TextOutput csv(o.output);
        const RenderInfo how{.source = std::filesystem::path(o.input).filename().string(),
                             .preset = {},
                             .changes = {},
                             .actuator = metered.size() == 1 ? metered[0].what.actuator.name : "",
                             .version = TACTUS_VERSION};
        // The header first, then how it was made as a comment line, as analyze's CSV: CSV
        // readers take the names from the first line and skip the comment. Several outputs:
        // each one's columns, prefixed with its name.
        std::ostream& out = csv.stream();
        out << "time_s";
        for (const Metered& m : metered) {
            const std::string prefix = m.name.empty() ? "" : m.name + "_";
            for (const auto& c : kChannels) out << ',' << prefix << c.name << "_sl_db";
            out << ',' << prefix << "combined_sl_db";
        }
        out << "\n# " << how.comment() << '\n';
        for (size_t i = 0; i < metered.front().readings.size(); ++i) {
            out << fmt::format("{:.2f}", metered.front().readings[i].time_s);
            for (const Metered& m : metered) {
                const perception::MeterReading& r = m.readings[i];
                for (double v : r.level_db) out << fmt::format(",{:.2f}", v);
                out << fmt::format(",{:.2f}", r.combined_db);
            }
            out << '\n';
        }
        csv.commit();
    }
    // The summary is data, on stdout, unless the CSV went there; written at once, so files
    // metered in parallel do not mix their lines.
    std::ostringstream summary;
    for (const Metered& m : metered) print_summary(summary, o, m, run.frames / run.sample_rate_hz);
    (!o.output.empty() && is_stdout(o.output) ? std::cerr : std::cout)
        << summary.str() << std::flush;
}

}  // namespace

void add_meter(CLI::App& app) {
    auto options = std::make_shared<MeterOptions>();
    CLI::App* command =
        app.add_subcommand("meter",
                           "sensation level of each channel of touch (P, NPI, NPII, NPIII) for a "
                           "vibration file driving an actuator");
    options->batch.add_to(*command,
                          "FILE.csv: sensation levels every 10 ms (dB SL, 0 = not engaged), one "
                          "input",
                          ".meter.csv");
    add_actuator_option(
        *command, options->actuator,
        "actuator profile (name in actuators/ or FILE.toml; default: the one the file was "
        "rendered for, as its comment says, else voice-coil)");
    command
        ->add_option("--contact-area", options->contact_area_cm2,
                     "skin contact area, cm2 (P channel spatial summation)")
        ->check(CLI::Range(spec(P::perception_contact_area_cm2).min,
                           spec(P::perception_contact_area_cm2).max))
        ->capture_default_str();
    command->callback([options] { for_each_input(*options, ".meter.csv", meter); });
}

}  // namespace tactus::cli
