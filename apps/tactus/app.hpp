// What every program of the command line shares around its commands (the `tactus` program and
// the helper programs it runs for the live and studio commands, helper_programs.hpp): the app's
// description, one-line errors, the global options, outputs removed on signals, and the run.
#pragma once

#include <CLI/CLI.hpp>

namespace tactus::cli {

// The app before its commands are added. Main thread, once.
void set_up_app(CLI::App& app);
// Parses the command line and runs the chosen command; the process's exit code.
int run_app(CLI::App& app, int argc, char** argv);

}  // namespace tactus::cli
