// tactus-studio: `tactus studio`, run by `tactus` in its place (helper_programs.hpp) with the
// same arguments: the only program that loads cpp-httplib (and OpenSSL, brotli).
#include <CLI/CLI.hpp>

#include "app.hpp"
#include "commands.hpp"

// NOLINTNEXTLINE(bugprone-exception-escape): only set-up errors (bad_alloc) escape: they abort
int main(int argc, char** argv) {
    CLI::App app;
    tactus::cli::set_up_app(app);
    tactus::cli::add_studio(app);
    return tactus::cli::run_app(app, argc, argv);
}
