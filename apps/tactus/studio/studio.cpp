// tactus studio [FILE...]: a designer's studio in the browser. Serves one page (page.html) on
// loopback with a random token in its URL (printed on stdout, opened in a browser where there
// is a display): sound files from the command line or dropped on the page, the report's plots
// on one time axis, a control for every parameter, sound and vibration played together, A/B
// and undo, presets saved and every format of `tactus export` written, each rendered by the
// same code as `tactus render` and `tactus export`.
#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <iostream>
#include <thread>

#include "commands.hpp"
#include "common.hpp"
#include "global_options.hpp"
#include "helper_commands.hpp"
#include "server.hpp"
#include "session.hpp"

extern char** environ;

namespace tactus::cli {
namespace {

struct StudioOptions {
    std::vector<std::string> files;
    std::string host = "127.0.0.1";
    int port = 0;
    bool no_browser = false;
};

// xdg-open URL, where there is a display; a missing opener is no error (the URL is printed).
void open_browser(const std::string& url) {
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    std::string program = "xdg-open";
    std::string argument = url;
    char* argv[] = {program.data(), argument.data(), nullptr};
    pid_t pid = 0;
    if (posix_spawnp(&pid, "xdg-open", &actions, nullptr, argv, environ) == 0)
        std::thread([pid] { waitpid(pid, nullptr, 0); }).detach();
    posix_spawn_file_actions_destroy(&actions);
}

void studio(const StudioOptions& o) {
    std::vector<std::filesystem::path> files;
    for (const auto& f : o.files) {
        check_input(f, false);
        if (f == "-") throw std::runtime_error("-: the studio reads files, not standard input");
        files.emplace_back(f);
    }
    StudioSession session(files);
    serve_studio(session, o.host, o.port, [&](int port) {
        const std::string url =
            fmt::format("http://{}:{}/?token={}", o.host, port, session.token());
        std::cout << url << std::endl;
        note(fmt::format("tactus studio: {} file(s), listening on {}:{} (Ctrl-C ends it)",
                         files.size(), o.host, port));
        if (!o.no_browser) open_browser(url);
    });
}

}  // namespace

void add_studio(CLI::App& app) {
    auto options = std::make_shared<StudioOptions>();
    CLI::App* command = app.add_subcommand(kStudioCommand.name, kStudioCommand.description);
    command->add_option("files", options->files, "sound files to open (more can be dropped)");
    command
        ->add_option("--host", options->host,
                     "address to listen on (another than loopback lets other machines in)")
        ->capture_default_str();
    command->add_option("--port", options->port, "port to listen on (0: any free port)")
        ->check(CLI::Range(0, 65535))
        ->capture_default_str();
    command->add_flag("--no-browser", options->no_browser, "print the URL, open no browser");
    command->callback([options] { studio(*options); });
}

}  // namespace tactus::cli
