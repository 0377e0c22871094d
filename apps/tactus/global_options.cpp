#include "global_options.hpp"

#include <iostream>

#include "tactus/core/nearest.hpp"

namespace tactus::cli {
namespace {
bool g_quiet = false;
}  // namespace

void add_global_options(CLI::App& app) {
    app.set_version_flag("--version", "tactus " TACTUS_VERSION);
    app.add_flag("--quiet,-q", g_quiet, "no warnings or summaries on stderr, errors only");
    app.fallthrough();  // the flags above also after the command
}

int command_index(int argc, const char* const* argv) {
    int first = 1;
    while (first < argc &&
           (std::string(argv[first]) == "-q" || std::string(argv[first]) == "--quiet"))
        ++first;
    return first < argc && argv[first][0] != '-' ? first : 0;
}

std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv) {
    const int first = command_index(argc, argv);
    if (first == 0) return std::nullopt;
    std::vector<std::string> names;
    for (const CLI::App* command : app.get_subcommands({})) {
        if (command->get_name() == argv[first]) return std::nullopt;
        names.push_back(command->get_name());
    }
    const std::string nearest = nearest_name(argv[first], names);
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    return "unknown command '" + std::string(argv[first]) + "' (" +
           (nearest.empty() ? "" : "did you mean '" + nearest + "'? ") + "commands: " + known + ")";
}

bool quiet() {
    return g_quiet;
}

void note(const std::string& line) {
    if (!g_quiet) std::cerr << line << '\n';
}

}  // namespace tactus::cli
