// What every command shares on the command line: --version, --quiet (no warnings or summaries
// on stderr, errors only), and a mistyped command answered with the one that was meant.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace tactus::cli {

// --version and --quiet, given before or after the command.
void add_global_options(CLI::App& app);
// The index in argv of the command's name: the first argument after the global options; 0 when
// there is none (no argument, or an option first).
int command_index(int argc, const char* const* argv);
// "unknown command 'rendr' (did you mean 'render'?)" when the first argument names no command.
std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv);
// Whether --quiet was given.
bool quiet();
// A warning or a summary line on stderr, unless --quiet.
void note(const std::string& line);

}  // namespace tactus::cli
