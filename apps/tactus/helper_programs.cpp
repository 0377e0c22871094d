#include "helper_programs.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>

#include "global_options.hpp"
#include "helper_commands.hpp"

namespace tactus::cli {
namespace {

// The helpers' commands built with this program.
constexpr HelperCommand kBuilt[] = {
#ifdef TACTUS_STUDIO
    kStudioCommand,
#endif
#ifdef TACTUS_LIVE
    kLiveCommand,
    kDevicesCommand,
    kCalibrateCommand,
#endif
    {nullptr, nullptr, nullptr}};

}  // namespace

void add_helper_commands(CLI::App& app, char** argv) {
    for (const HelperCommand& command : kBuilt) {
        if (!command.name) break;
        CLI::App* listed = app.add_subcommand(command.name, command.description);
        // Reached only if chosen_helper_command did not see it: the helper parses all the same.
        listed->allow_extras()->prefix_command();
        listed->callback([&command, argv] { run_helper(command, argv); });
    }
}

const HelperCommand* chosen_helper_command(int argc, const char* const* argv) {
    const int index = command_index(argc, argv);
    if (index == 0) return nullptr;
    for (const HelperCommand& command : kBuilt)
        if (command.name && std::strcmp(command.name, argv[index]) == 0) return &command;
    return nullptr;
}

void run_helper(const HelperCommand& command, char** argv) {
    namespace fs = std::filesystem;
    std::error_code error;
    const fs::path program = fs::read_symlink("/proc/self/exe", error);
    const fs::path helper = program.parent_path() / TACTUS_HELPER_DIR / command.program;
    if (!error) execv(helper.c_str(), argv);  // the same arguments, argv[0] too: the same --help
    std::cerr << "tactus: error: `tactus " << command.name << "` needs its program '"
              << helper.lexically_normal().string()
              << "': " << (error ? error.message() : std::strerror(errno)) << '\n';
    std::exit(1);
}

}  // namespace tactus::cli
