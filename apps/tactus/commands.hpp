// The `tactus` subcommands; each registers itself on the app.
#pragma once

#include <CLI/CLI.hpp>

namespace tactus::cli {

void add_render(CLI::App& app);
void add_analyze(CLI::App& app);
void add_onsets(CLI::App& app);
void add_presets(CLI::App& app);
void add_placement(CLI::App& app);
void add_meter(CLI::App& app);
void add_simulate(CLI::App& app);
void add_export(CLI::App& app);
void add_actuators(CLI::App& app);
void add_report(CLI::App& app);
// In the helper programs (helper_programs.hpp): tactus-studio, with cpp-httplib
void add_studio(CLI::App& app);  // studio/
// and tactus-live, with the live front end (live/)
void add_live(CLI::App& app);       // live.cpp
void add_devices(CLI::App& app);    // devices.cpp
void add_calibrate(CLI::App& app);  // calibrate.cpp

}  // namespace tactus::cli
