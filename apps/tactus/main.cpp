// tactus: music -> vibrotactile feedback. Data on stdout, messages on stderr, non-zero exit on
// any error. The live and studio commands are run by helper programs (helper_programs.hpp), so
// that the other commands load none of their libraries.
#include <CLI/CLI.hpp>
#include <cstring>

#include "app.hpp"
#include "commands.hpp"
#include "global_options.hpp"
#include "helper_programs.hpp"

namespace {

// This program's commands, by the name each registers. Only the chosen command's options are
// built (building every command's took 1.3 M instructions at each start); all of them when none
// is named (--help, --version) or the name is unknown (answered with the known ones).
struct Command {
    const char* name;
    void (*add)(CLI::App&);
};
constexpr Command kCommands[] = {
    {"render", tactus::cli::add_render},       {"analyze", tactus::cli::add_analyze},
    {"onsets", tactus::cli::add_onsets},       {"presets", tactus::cli::add_presets},
    {"placement", tactus::cli::add_placement}, {"meter", tactus::cli::add_meter},
    {"simulate", tactus::cli::add_simulate},   {"export", tactus::cli::add_export},
    {"actuators", tactus::cli::add_actuators}, {"report", tactus::cli::add_report},
};

}  // namespace

// NOLINTNEXTLINE(bugprone-exception-escape): only set-up errors (bad_alloc) escape: they abort
int main(int argc, char** argv) {
    if (const auto* helper = tactus::cli::chosen_helper_command(argc, argv))
        tactus::cli::run_helper(*helper, argv);
    CLI::App app;
    tactus::cli::set_up_app(app);
    const int chosen = tactus::cli::command_index(argc, argv);
    for (const Command& command : kCommands)
        if (chosen != 0 && std::strcmp(command.name, argv[chosen]) == 0) {
            command.add(app);
            return tactus::cli::run_app(app, argc, argv);
        }
    for (const Command& command : kCommands) command.add(app);
    tactus::cli::add_helper_commands(app, argv);
    return tactus::cli::run_app(app, argc, argv);
}
