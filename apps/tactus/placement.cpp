// tactus placement MEASUREMENTS.csv [-o FILE.csv]: per tonehole size, the skin extension across
// fingers and subjects, the recommended actuator depth and the hole with the least variation
// (paper §4, Figure 2). -o writes one row per measurement with its hole's statistics: points and
// mean line of Figure 2, ready to plot.
#include "tactus/placement/placement.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "commands.hpp"
#include "common.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus::cli {
namespace {

struct PlacementOptions {
    std::string input, output;
    bool force = false;
};

std::string mm(double value) {
    return std::isnan(value) ? "-" : fmt::format("{:.3f}", value);
}

void write_plot_csv(std::ostream& out, std::vector<Measurement> rows,
                    const PlacementReport& report) {
    std::sort(rows.begin(), rows.end(), [](const Measurement& a, const Measurement& b) {
        return std::tie(a.hole_mm, a.subject, a.finger) < std::tie(b.hole_mm, b.subject, b.finger);
    });
    out << "hole_mm,subject,finger,extension_mm,mean_mm,sd_mm,n,depth_mm\n";
    for (const Measurement& m : rows) {
        const auto& h = *std::find_if(report.holes.begin(), report.holes.end(),
                                      [&](const HoleSummary& s) { return s.hole_mm == m.hole_mm; });
        out << fmt::format(
            "{:g},{},{},{:g},{:.4f},{},{},{:.4f}\n", m.hole_mm, m.subject, m.finger, m.extension_mm,
            h.mean_mm, std::isnan(h.sd_mm) ? "" : fmt::format("{:.4f}", h.sd_mm), h.n, h.depth_mm);
    }
}

void placement(const PlacementOptions& o) {
    check_input(o.input, false);
    const std::vector<Measurement> rows = read_measurements(o.input);
    const PlacementReport report = summarise_placement(rows);
    if (!is_stdout(o.output)) check_output(o.input, o.output, o.force);

    std::cout << fmt::format("{:>8} {:>4} {:>8} {:>8} {:>8} {:>8} {:>8} {:>9}\n", "hole_mm", "n",
                             "subjects", "mean_mm", "sd_mm", "min_mm", "max_mm", "depth_mm");
    for (const HoleSummary& h : report.holes)
        std::cout << fmt::format("{:>8g} {:>4} {:>8} {:>8} {:>8} {:>8} {:>8} {:>9}\n", h.hole_mm,
                                 h.n, h.subjects, mm(h.mean_mm), mm(h.sd_mm), mm(h.min_mm),
                                 mm(h.max_mm), mm(h.depth_mm));
    std::cout << "depth_mm: recommended actuator depth below the surround = mean - SD of the skin "
                 "extension (most fingers just touch it)\n";
    if (report.least_variation) {
        const HoleSummary& best = report.holes[*report.least_variation];
        std::cout << fmt::format(
            "least variation: {:g} mm hole (SD {:.3f} mm over {} fingers of {} subjects); "
            "actuator {:.3f} mm below the surround\n",
            best.hole_mm, best.sd_mm, best.n, best.subjects, best.depth_mm);
    } else {
        std::cout << "least variation: none (every hole has a single measurement)\n";
    }

    if (o.output.empty()) return;
    TextOutput output(o.output);
    write_plot_csv(output.stream(), rows, report);
    output.commit();
    std::cerr << fmt::format("{}: {} measurements, {} hole sizes\n", o.output, rows.size(),
                             report.holes.size());
}

}  // namespace

void add_placement(CLI::App& app) {
    auto options = std::make_shared<PlacementOptions>();
    CLI::App* command = app.add_subcommand(
        "placement", "tonehole size vs skin extension: actuator depth and the steadiest hole");
    command
        ->add_option("measurements", options->input,
                     "CSV with the header subject,finger,hole_mm,extension_mm ('#' comments)")
        ->required()
        ->type_name("FILE");
    command->add_option("-o,--output", options->output,
                        "plot-ready CSV: every measurement with its hole's mean, SD, n, depth");
    add_force_option(*command, options->force);
    command->callback([options] { placement(*options); });
}

}  // namespace tactus::cli
