// How every command takes many inputs, the same way: files and folders (walked for sound files)
// as inputs; with -O DIR each input's output is DIR/<its folder below the input folder>/<its
// name without extension><suffix>, folders created, so a tree of sounds gives the same tree of
// outputs; --skip-existing leaves outputs that exist (a batch can be resumed); two inputs that
// would write one output are refused before any audio is read; a failed file is named on stderr,
// the others are written, and the exit code is non-zero. One input may go to -o (or stdout).
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace tactus::cli {

struct BatchOptions {
    std::vector<std::string> inputs;
    std::string output, output_dir;
    bool skip_existing = false, force = false;
    int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

    // inputs (positional), -o (help given), -O, -j, --skip-existing, --force.
    void add_to(CLI::App& command, const std::string& output_help, const std::string& suffix);
};

struct BatchJob {
    std::filesystem::path input, output;  // one input without -O: output is -o as given
};

// The jobs: every input (folders walked), its output, checked (check_output: never the input,
// an existing output only with --force) before any audio is read. Skipped outputs are left out
// and counted in `skipped`.
std::vector<BatchJob> plan_batch(const BatchOptions& o, const std::string& suffix, size_t& skipped);

// Runs `one` for every job (in parallel with -O; folders of outputs created), then reports
// failures as render does; throws when any failed.
void run_jobs(const BatchOptions& o, const std::vector<BatchJob>& jobs, const std::string& label,
              const std::function<void(const BatchJob& job)>& one);

}  // namespace tactus::cli
