// `tactus export`'s options and its one-input export, shared with `tactus studio` (which writes
// the same files the command would write).
#pragma once

#include <string>
#include <vector>

#include "batch_plan.hpp"
#include "pipeline_options.hpp"
#include "tactus/export/normalisation.hpp"

namespace tactus::cli {

struct ExportOptions {
    std::string input, actuator;
    std::string layout;  // each output's files named by it (OUT.<name>.ahap); the .ogg carries all
    std::vector<std::string> outputs;  // -o, repeatable: one input's outputs
    int channels = 1;
    bool force = false;
    std::string normalise = Normalisation{}.name();
    double gain_db = 0;
    PipelineOptions pipeline;
    // A batch (batch_plan.hpp), and with -O the formats each input is written in.
    BatchOptions batch;
    std::vector<std::string> formats{".ahap", ".haptic", ".android.json", ".envelope.json", ".ogg"};
};

// Renders o.input once and writes every one of o.outputs (each format named by its ending), all
// or none; throws std::runtime_error with a one-line message naming the file.
void export_files(const ExportOptions& o);

}  // namespace tactus::cli
