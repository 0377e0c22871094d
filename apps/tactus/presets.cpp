// tactus presets [--params | --show NAME | --save FILE]: the presets found, the parameter table
// they draw on, one preset's values, or a preset (--preset and --set applied) saved with every
// parameter.
#include <fmt/format.h>

#include <iostream>

#include "commands.hpp"
#include "common.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/io/text_output.hpp"
#include "tactus/params/params.hpp"

namespace tactus::cli {
namespace {

void print_params() {
    constexpr std::string_view kRow = "{:>3} {:<36} {:<7} {:>10} {:>10} {:>10} {:<4} {:<10}  {}\n";
    std::cout << fmt::format(kRow, "id", "key", "type", "default", "min", "max", "unit", "change",
                             "help");
    const Settings defaults;
    for (const ParamSpec& s : param_table()) {
        std::string range_min = fmt::format("{:g}", s.min), range_max = fmt::format("{:g}", s.max);
        if (!s.choices.empty()) range_min = range_max = "";
        const std::string change = s.change == ParamChange::structural ? "structural"
                                   : s.smoothing_ms > 0 ? fmt::format("{:g} ms", s.smoothing_ms)
                                                        : "live";
        std::cout << fmt::format(kRow, s.id, s.key, kParamTypeNames[static_cast<int>(s.type)],
                                 defaults.text_of(s.param), range_min, range_max, s.unit, change,
                                 s.help);
    }
}

// Every parameter's value in a preset (with --set applied), its unit, and '*' where it differs
// from the parameter's default.
void show_preset(const std::string& name, const std::vector<std::string>& assignments) {
    const std::filesystem::path path = resolve_preset(name);
    Settings settings;
    apply_preset_file(settings, path);
    for (const auto& a : assignments) apply_assignment(settings, a);
    std::cout << fmt::format("# {} ({}); * = not the default\n", name, path.string());
    const Settings defaults;
    for (const ParamSpec& s : param_table()) {
        const bool changed = settings[s.param] != defaults[s.param];
        std::cout << fmt::format("{} {:<36} {:>12} {:<4} {}\n", changed ? '*' : ' ', s.key,
                                 settings.text_of(s.param), s.unit,
                                 changed ? "(default " + defaults.text_of(s.param) + ")" : "");
    }
}

struct Options {
    bool params = false;
    std::string show;
    std::filesystem::path save;
    std::string description;
    bool force = false;
    PipelineOptions pipeline;
};

// Every parameter of --preset with --set applied, written atomically to options.save.
void save_preset(const Options& o) {
    const std::filesystem::path source = resolve_preset(o.pipeline.preset);
    if (!is_stdout(o.save)) check_output(source, o.save, o.force);
    const Settings settings = o.pipeline.resolve();
    const std::string description =
        o.description.empty() ? o.pipeline.description() : o.description;
    TextOutput out(o.save);
    out.stream() << preset_text(settings, description);
    out.commit();
}

}  // namespace

void add_presets(CLI::App& app) {
    auto options = std::make_shared<Options>();
    CLI::App* command =
        app.add_subcommand("presets", "list, describe or save presets (TOML files)");
    command->add_flag("--params", options->params,
                      "list every parameter a preset or --set can change");
    command
        ->add_option("--save", options->save,
                     "write --preset with --set applied, every parameter, to FILE.toml (- for "
                     "stdout)")
        ->excludes("--params");
    command
        ->add_option("--show", options->show,
                     "every parameter's value in preset NAME (or FILE.toml), --set applied")
        ->excludes("--params");
    command->add_option("--description", options->description,
                        "the saved preset's description (default: how it was made)");
    options->pipeline.add_to(*command);
    add_force_option(*command, options->force);
    command->callback([options] {
        if (options->params) return print_params();
        if (!options->show.empty())
            return show_preset(options->show, options->pipeline.assignments);
        if (!options->save.empty()) return save_preset(*options);
        for (const auto& p : list_presets())
            std::cout << fmt::format("{:<16} {}  ({})\n", p.name, p.description, p.path.string());
    });
}

}  // namespace tactus::cli
