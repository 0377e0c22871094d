// tactus: music -> vibrotactile feedback. Data on stdout, messages on stderr, non-zero exit on
// any error. The live and studio commands are run by helper programs (helper_programs.hpp), so
// that the other commands load none of their libraries.
#include <CLI/CLI.hpp>

#include "app.hpp"
#include "commands.hpp"
#include "helper_programs.hpp"

// NOLINTNEXTLINE(bugprone-exception-escape): only set-up errors (bad_alloc) escape: they abort
int main(int argc, char** argv) {
    if (const auto* helper = tactus::cli::chosen_helper_command(argc, argv))
        tactus::cli::run_helper(*helper, argv);
    CLI::App app;
    tactus::cli::set_up_app(app);
    tactus::cli::add_render(app);
    tactus::cli::add_analyze(app);
    tactus::cli::add_onsets(app);
    tactus::cli::add_presets(app);
    tactus::cli::add_placement(app);
    tactus::cli::add_meter(app);
    tactus::cli::add_simulate(app);
    tactus::cli::add_export(app);
    tactus::cli::add_actuators(app);
    tactus::cli::add_report(app);
    tactus::cli::add_helper_commands(app, argv);
    return tactus::cli::run_app(app, argc, argv);
}
