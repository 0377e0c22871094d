// --preset and --set, shared by every command that runs the pipeline. Resolved (and so
// validated) before any audio is read.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tactus/params/params.hpp"

namespace tactus::cli {

struct PipelineOptions {
    std::string preset = "tfd";
    std::vector<std::string> assignments;

    void add_to(CLI::App& command);
    Settings resolve() const;  // throws with a one-line message
};

}  // namespace tactus::cli
