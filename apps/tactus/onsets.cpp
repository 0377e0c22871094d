// tactus onsets IN: one onset per line, "onset_s decided_s strength_db part". The first column
// alone is an onset list as aubioonset prints it and as onset evaluation tools read it; decided_s
// is when the onset was decided (its pulse starts), strength_db what the hit added above what was
// sounding and part its drum part, both read parts.settle_ms after the onset
// (analysis/hit_analysis.hpp). --part-features adds the numbers each part was decided on, which
// eval/fit_parts.py fits the models on: the part model's (analysis/part_features.hpp; nan where
// it did not read the onset), then the onset model's (analysis/onset_rises.hpp; nan where the
// next onset came before the part, or the input has no 6-10 kHz band to read them on).
#include <fmt/format.h>

#include <limits>
#include <span>

#include "batch_plan.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "pipeline_options.hpp"
#include "tactus/engine/onset_decisions.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus::cli {
namespace {

struct OnsetsOptions {
    std::string input, output;
    bool force = false, part_features = false;
    BatchOptions batch;
    PipelineOptions pipeline;
};

// Only the onset detector and the spectrum its parts are read from run: the other features and
// the vibration are not computed, the onsets are those `render` triggers pulses on.
void onsets(const OnsetsOptions& o) {
    const Settings settings = o.pipeline.resolve();
    if (!is_stdout(o.output)) check_output(o.input, o.output, o.force);
    TextOutput output(o.output);
    std::ostream& out = output.stream();
    Analyzer analyzer;
    analyzer.read_every_onset(o.part_features);
    double sample_rate_hz = 0;
    Progress progress("onsets");
    OnsetDecisions decisions;
    const auto print = [&](const DecidedOnset& onset) {
        out << fmt::format("{:.6f} {:.6f} {:.2f} {}", onset.onset_sample / sample_rate_hz,
                           onset.decided_sample / sample_rate_hz, onset.strength_db,
                           name_of(onset.part));
        if (o.part_features) {
            // Called on the frame that decided the part, so the analysis still holds it.
            const HitAnalysis& hits = analyzer.hits();
            const auto numbers = [&](std::span<const float> values, bool read) {
                for (const float value : values)
                    out << fmt::format(" {:.5g}",
                                       read ? value : std::numeric_limits<float>::quiet_NaN());
            };
            numbers(hits.part_features(), onset.part_decided && hits.part_features_read());
            numbers(hits.onset_rises(), onset.part_decided && hits.onset_rises_read());
        }
        out << '\n';
    };
    analyse_file(
        o.input, analyzer, settings, OnsetDecisions::reads(),
        [&](const Features& f) { decisions.add(f, print); },
        with_progress(progress,
                      {.on_start = [&](double rate_hz, int) { sample_rate_hz = rate_hz; }}));
    decisions.finish(print);
    output.commit();
}

}  // namespace

void add_onsets(CLI::App& app) {
    auto options = std::make_shared<OnsetsOptions>();
    CLI::App* command = app.add_subcommand(
        "onsets", "print one onset per line: onset_s decided_s strength_db part");
    options->batch.add_to(*command, "file to write, one input (default: stdout)", ".onsets.txt");
    options->pipeline.add_to(*command);
    command->add_flag("--part-features", options->part_features,
                      "after each part, the numbers it was decided on: the part model's, then the "
                      "onset model's (eval/fit_parts.py)");
    command->callback([options] { for_each_input(*options, ".onsets.txt", onsets); });
}

}  // namespace tactus::cli
