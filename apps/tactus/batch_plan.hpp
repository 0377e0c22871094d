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

// A command run once per input, as render is: `run` gets a copy of `options` with one input, its
// output (DIR/<name><suffix> with -O) and --force. Options has input, output, force and batch.
template <typename Options>
void for_each_input(const Options& options, const std::string& suffix, const std::string& label,
                    void (*run)(const Options&)) {
    size_t skipped = 0;
    const std::vector<BatchJob> jobs = plan_batch(options.batch, suffix, skipped);
    run_jobs(options.batch, jobs, label, [&](const BatchJob& job) {
        Options one = options;
        one.input = job.input.string(), one.output = job.output.string();
        one.force = options.batch.force;
        run(one);
    });
}

// Says on stderr why each failed job failed; throws "LABEL: N of M files failed, the others
// were written" when any did.
void report_failures(const std::string& label, const std::vector<std::exception_ptr>& errors);

}  // namespace tactus::cli
