// --preset and --set, shared by every command that runs the pipeline. Resolved (and so
// validated) before any audio is read.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "tactus/io/preset.hpp"
#include "tactus/io/render_info.hpp"
#include "tactus/params/params.hpp"

namespace tactus::cli {

struct PipelineOptions {
    std::string preset = kDefaultPreset;
    std::vector<std::string> assignments;

    void add_to(CLI::App& command);
    Settings resolve() const;  // throws with a one-line message
    // How an output of `input` was made with these options, for its metadata.
    RenderInfo render_info(const std::string& input, const std::string& actuator) const;
    // A saved preset's description: "from <preset> key=value ...".
    std::string description() const;
};

}  // namespace tactus::cli
