// `tactus live`, `devices`, `calibrate` and `studio` run by their helper programs
// (helper_commands.hpp), found at PROGRAM_DIR/TACTUS_HELPER_DIR (../libexec/tactus, in the build
// tree as in an installed one: no absolute path compiled in).
//
// Why programs of their own rather than a module `tactus` would dlopen: a module needs the
// program's code too (the engine, the options shared by every command, --quiet's state), either
// exported by the program (every symbol dynamic: a bigger program, slower to start) or copied
// into the module (two copies of global state: --quiet parsed by one and read by the other, two
// lists of temporary outputs for the signal handlers). A helper parses the whole command line
// itself and shares nothing at run time, and exec keeps the process (its id, signals, standard
// streams, exit code), so callers see `tactus` as before.
#pragma once

#include <CLI/CLI.hpp>

namespace tactus::cli {

struct HelperCommand;

// Lists the helpers' commands that were built on the app, for `tactus --help`. Main thread.
void add_helper_commands(CLI::App& app, char** argv);
// The helper's command the command line chooses, if any (global options before it skipped).
const HelperCommand* chosen_helper_command(int argc, const char* const* argv);
// Runs the command's helper with the same arguments in place of this process; returns only if it
// cannot (the one-line error printed, exit code 1). Main thread, with no other thread running.
[[noreturn]] void run_helper(const HelperCommand& command, char** argv);

}  // namespace tactus::cli
