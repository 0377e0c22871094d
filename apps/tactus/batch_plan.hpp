// How every command takes many inputs, the same way: files and folders (walked for sound files)
// as inputs; with -O DIR each input's output is DIR/<its folder below the input folder>/<its
// name without extension><suffix>, folders created, so a tree of sounds gives the same tree of
// outputs; --skip-existing leaves outputs that exist (a batch can be resumed); two inputs that
// would write one output are refused before any audio is read; a failed file is named on stderr,
// the others are written, and the exit code is non-zero. One input may go to -o (or stdout).
// Every command that takes several inputs goes through here, so all say the same words.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "batch.hpp"

namespace tactus::cli {

struct BatchOptions {
    std::vector<std::string> inputs;
    std::string output, output_dir;
    bool skip_existing = false, force = false;
    int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::string command;         // its name, for the messages (set by add_to)
    bool output_needed = false;  // writes a file, never stdout: -o or -O must be given

    // inputs (positional), -o (when output_help is not empty: a command with its own -o sets
    // `output` to its first before planning), -O, -j, --skip-existing, --force.
    void add_to(CLI::App& command, const std::string& output_help, const std::string& suffix);
};

struct BatchJob {
    std::filesystem::path input, output;  // one input without -O: output is -o as given
};

// The jobs: every input (folders walked), its output, checked (check_output: never the input,
// an existing output only with --force) before any audio is read. Skipped outputs are left out
// and counted in `skipped`.
std::vector<BatchJob> plan_batch(const BatchOptions& o, const std::string& suffix, size_t& skipped);

// One job: writes job's output(s), counts its frames for the bar; returns a line said once the
// whole batch is over (in the inputs' order, after the bar), or "".
using JobTask = std::function<std::string(const BatchJob& job, const AddFrames& add_frames)>;

// Runs `one` for every job, in parallel on -j threads (folders of outputs created first), says
// each success's line, then each failure on stderr; throws when any failed (one job: its own
// error). With `total_frames` the batch draws one bar by frames, even for one job; without it a
// lone job runs here, drawing its own bar, and several get a bar by files.
void run_jobs(const BatchOptions& o, const std::vector<BatchJob>& jobs, const JobTask& one,
              const std::function<int64_t()>& total_frames = {});

// A command run once per input: `run` gets a copy of `options` with one input, its output
// (DIR/<name><suffix> with -O) and --force. Options has input, output, force and batch.
template <typename Options>
void for_each_input(const Options& options, const std::string& suffix,
                    void (*run)(const Options&)) {
    size_t skipped = 0;
    const std::vector<BatchJob> jobs = plan_batch(options.batch, suffix, skipped);
    run_jobs(options.batch, jobs, [&](const BatchJob& job, const AddFrames&) {
        Options one = options;
        one.input = job.input.string(), one.output = job.output.string();
        one.force = options.batch.force;
        run(one);
        return std::string();
    });
}

// Says on stderr why each failed job failed; throws "LABEL: N of M files failed, the others
// were written" when any did.
void report_failures(const std::string& label, const std::vector<std::exception_ptr>& errors);

}  // namespace tactus::cli
