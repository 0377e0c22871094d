// Small helpers shared by the commands.
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "progress.hpp"
#include "tactus/io/run_file.hpp"

namespace tactus::cli {

// Refuses an output path that names the input file itself: inputs are never overwritten.
inline void refuse_overwriting_input(const std::filesystem::path& input,
                                     const std::filesystem::path& output) {
    std::error_code error;
    if (std::filesystem::equivalent(input, output, error))
        throw std::runtime_error(
            fmt::format("{}: output would overwrite the input file", output.string()));
}

// Runs `engine` over `input` with a progress bar labelled `label`.
inline RunSummary run_with_progress(const std::string& input, Engine& engine,
                                    const std::string& label, RunCallbacks callbacks = {}) {
    Progress progress(label);
    callbacks.on_progress = [&](int64_t done, int64_t total) { progress.update(done, total); };
    return run_file(input, engine, callbacks);
}

}  // namespace tactus::cli
