// tactus: music -> vibrotactile feedback. Data on stdout, messages on stderr, non-zero exit on
// any error.
#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"
#include "global_options.hpp"
#include "tactus/io/temporary_path.hpp"

// NOLINTNEXTLINE(bugprone-exception-escape): only set-up errors (bad_alloc) escape: they abort
int main(int argc, char** argv) {
    CLI::App app{"tactus: turns music into vibrotactile feedback (Birnbaum & Wanderley's system)"};
    app.require_subcommand(1);
    app.failure_message([](const CLI::App*, const CLI::Error& e) {  // one line, like every error
        return std::string("tactus: error: ") + e.what() + '\n';
    });
    tactus::cli::add_global_options(app);
    tactus::remove_temporaries_on_signals();  // Ctrl-C or kill leaves no partial output
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
#ifdef TACTUS_STUDIO
    tactus::cli::add_studio(app);
#endif
#ifdef TACTUS_LIVE
    tactus::cli::add_live(app);
    tactus::cli::add_devices(app);
    tactus::cli::add_calibrate(app);
#endif
    if (const auto unknown = tactus::cli::unknown_command(app, argc, argv)) {
        std::cerr << "tactus: error: " << *unknown << '\n';
        return 1;  // an error tactus finds (docs/robustness.md, exit codes)
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::cerr << "tactus: error: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
