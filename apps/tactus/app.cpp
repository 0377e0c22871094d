#include "app.hpp"

#include <iostream>

#include "global_options.hpp"
#include "tactus/io/temporary_path.hpp"

namespace tactus::cli {

void set_up_app(CLI::App& app) {
    app.description(
        "tactus: turns music into vibrotactile feedback (Birnbaum & Wanderley's system)");
    app.require_subcommand(1);
    app.failure_message([](const CLI::App*, const CLI::Error& e) {  // one line, like every error
        return std::string("tactus: error: ") + e.what() + '\n';
    });
    add_global_options(app);
    remove_temporaries_on_signals();  // Ctrl-C or kill leaves no partial output
}

int run_app(CLI::App& app, int argc, char** argv) {
    if (const auto unknown = unknown_command(app, argc, argv)) {
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

}  // namespace tactus::cli
