// tactus meter FILE [--actuator NAME] [--contact-area CM2] [-o FILE.csv]: which channels of
// touch a vibration file engages through an actuator, and how strongly (dB SL over time). The
// file is the actuator's drive, metered through its model (actuator/drive_meter.hpp).
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

void print_summary(std::ostream& out, const MeterOptions& o, const ActuatorProfile& a,
                   double seconds, const perception::MeterSummary& s) {
    out << fmt::format(
        "{}: {:.2f} s through {} ({}, {:g} um at {:g} Hz full scale, {}), contact {:g} cm2\n",
        o.input, seconds, a.name, type_name(a.type), a.displacement_um, a.reference_hz,
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
    for (const auto& c : kChannels)
        row(c.name, c.sensation, s.channels[static_cast<int>(c.channel)]);
    row("combined", "", s.combined);
}

void meter(const MeterOptions& o) {
    if (!is_stdout(o.output)) check_output(o.input, o.output, o.force);
    const ActuatorProfile actuator = actuator_of_vibration(o.actuator, o.input, "metered");
    std::optional<TextOutput> csv;
    if (!o.output.empty()) {
        csv.emplace(o.output);
        const RenderInfo how{.source = std::filesystem::path(o.input).filename().string(),
                             .preset = {},
                             .changes = {},
                             .actuator = actuator.name,
                             .version = TACTUS_VERSION};
        // The header first, then how it was made as a comment line, as analyze's CSV: CSV
        // readers take the names from the first line and skip the comment.
        csv->stream() << "time_s";
        for (const auto& c : kChannels) csv->stream() << ',' << c.name << "_sl_db";
        csv->stream() << ",combined_sl_db\n# " << how.comment() << '\n';
    }
    perception::MeterSummariser summariser;
    const auto on_reading = [&](const perception::MeterReading& r) {
        summariser.add(r);
        if (!csv) return;
        std::ostream& out = csv->stream();
        out << fmt::format("{:.2f}", r.time_s);
        for (double v : r.level_db) out << fmt::format(",{:.2f}", v);
        out << fmt::format(",{:.2f}\n", r.combined_db);
    };
    Progress progress("meter");
    FileSource vibration(o.input, kStreamBlockFrames);
    const RunSummary run =
        meter_source(vibration, actuator, o.contact_area_cm2, on_reading, with_progress(progress));
    if (csv) csv->commit();
    // The summary is data, on stdout, unless the CSV went there; written at once, so files
    // metered in parallel do not mix their lines.
    std::ostringstream summary;
    print_summary(summary, o, actuator, run.frames / run.sample_rate_hz, summariser.summary());
    (csv && is_stdout(o.output) ? std::cerr : std::cout) << summary.str() << std::flush;
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
