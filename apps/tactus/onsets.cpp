// tactus onsets IN: one onset per line, "onset_s decided_s strength_db part". The first column
// alone is an onset list as aubioonset prints it and as onset evaluation tools read it; decided_s
// is when the onset was decided (its pulse starts), strength_db what the hit added above what was
// sounding and part its drum part, both read parts.settle_ms after the onset
// (analysis/hit_analysis.hpp).
#include <fmt/format.h>

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
    bool force = false;
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
    double sample_rate_hz = 0;
    Progress progress("onsets");
    OnsetDecisions decisions;
    const auto print = [&](const DecidedOnset& onset) {
        out << fmt::format("{:.6f} {:.6f} {:.2f} {}\n", onset.onset_sample / sample_rate_hz,
                           onset.decided_sample / sample_rate_hz, onset.strength_db,
                           name_of(onset.part));
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
    command->callback([options] { for_each_input(*options, ".onsets.txt", onsets); });
}

}  // namespace tactus::cli
