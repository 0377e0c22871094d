// tactus-live: `tactus live`, `tactus devices` and `tactus calibrate`, run by `tactus` in its
// place (helper_programs.hpp) with the same arguments: the only program that loads RtAudio,
// JACK, ALSA and liblo.
#include <CLI/CLI.hpp>

#include "app.hpp"
#include "commands.hpp"

// NOLINTNEXTLINE(bugprone-exception-escape): only set-up errors (bad_alloc) escape: they abort
int main(int argc, char** argv) {
    CLI::App app;
    tactus::cli::set_up_app(app);
    tactus::cli::add_live(app);
    tactus::cli::add_devices(app);
    tactus::cli::add_calibrate(app);
    return tactus::cli::run_app(app, argc, argv);
}
