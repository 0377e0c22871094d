// Small helpers shared by the commands.
#pragma once

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "progress.hpp"
#include "tactus/io/run_file.hpp"
#include "tactus/io/temporary_path.hpp"

namespace tactus::cli {

// Refuses an output path that names the input file itself: inputs are never overwritten.
inline void refuse_overwriting_input(const std::filesystem::path& input,
                                     const std::filesystem::path& output) {
    std::error_code error;
    if (std::filesystem::equivalent(input, output, error))
        throw std::runtime_error(
            fmt::format("{}: output would overwrite the input file", output.string()));
}

// Every command that writes a file checks its output with this before reading any audio: never
// the input itself, never an existing file unless `force`, and a directory that exists. Stdout,
// devices and pipes (also behind a symlink such as /dev/stdout) are written into, never
// replaced.
inline void check_output(const std::filesystem::path& input, const std::filesystem::path& output,
                         bool force) {
    refuse_overwriting_input(input, output);
    if (written_in_place(output)) return;  // stdout, a device or a pipe: written into
    std::error_code error;
    if (std::filesystem::is_directory(output, error))
        throw std::runtime_error(fmt::format("{}: is a directory", output.string()));
    if (!force && std::filesystem::exists(output, error))
        throw std::runtime_error(
            fmt::format("{}: already exists (use --force to replace it)", output.string()));
    const std::filesystem::path dir = output.has_parent_path() ? output.parent_path() : ".";
    if (!std::filesystem::is_directory(dir, error))
        throw std::runtime_error(fmt::format("{}: cannot write: directory '{}' does not exist",
                                             output.string(), dir.string()));
}

// Every command's input paths, checked before any output is opened: one message for a path
// that does not exist, and tactus's exit code for errors (1; CLI11's validators would exit 105
// with their own words). "-" is standard input; `directory_allowed` for commands that walk
// folders.
inline void check_input(const std::filesystem::path& input, bool directory_allowed) {
    if (input == "-") return;
    std::error_code error;
    const auto status = std::filesystem::status(input, error);  // through symlinks
    if (status.type() == std::filesystem::file_type::not_found)
        throw std::runtime_error(fmt::format("{}: no such file or directory", input.string()));
    if (error) throw std::runtime_error(fmt::format("{}: {}", input.string(), error.message()));
    if (!directory_allowed && status.type() == std::filesystem::file_type::directory)
        throw std::runtime_error(fmt::format("{}: is a directory, not a file", input.string()));
}

// The --force flag of every command that writes a file.
inline void add_force_option(CLI::App& command, bool& force) {
    command.add_flag("--force", force, "replace an existing output file");
}

// `callbacks` with their progress drawn on `progress`.
inline RunCallbacks with_progress(Progress& progress, RunCallbacks callbacks = {}) {
    callbacks.on_progress = [&progress](int64_t done, int64_t total) {
        progress.update(done, total);
    };
    return callbacks;
}

// Runs `engine` over `input` with a progress bar labelled `label`.
inline RunSummary run_with_progress(const std::string& input, Engine& engine,
                                    const std::string& label, RunCallbacks callbacks = {}) {
    Progress progress(label);
    return run_file(input, engine, with_progress(progress, std::move(callbacks)));
}

}  // namespace tactus::cli
