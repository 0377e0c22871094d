#include "pipeline_options.hpp"

#include <filesystem>

#include "tactus/io/preset.hpp"

namespace tactus::cli {

void PipelineOptions::add_to(CLI::App& command) {
    command.add_option("--preset,-p", preset, "preset name (see `tactus presets`) or FILE.toml")
        ->capture_default_str();
    command.add_option("--set,-s", assignments, "override a parameter: key=value (repeatable)")
        ->take_all();
}

Settings PipelineOptions::resolve() const {
    Settings settings;
    apply_preset_file(settings, resolve_preset(preset));
    for (const auto& a : assignments) apply_assignment(settings, a);
    return settings;
}

RenderInfo PipelineOptions::render_info(const std::string& input,
                                        const std::string& actuator) const {
    return {.source = std::filesystem::path(input).filename().string(),
            .preset = preset,
            .changes = assignments,
            .actuator = actuator,
            .version = TACTUS_VERSION};
}

std::string PipelineOptions::description() const {
    std::string text = "from " + preset;
    for (const auto& a : assignments) text += " " + a;
    return text;
}

}  // namespace tactus::cli
