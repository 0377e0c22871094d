// tactus presets [--params]: the presets found, or the parameter table they draw on.
#include <fmt/format.h>

#include <iostream>

#include "commands.hpp"
#include "tactus/params/params.hpp"
#include "tactus/io/preset.hpp"

namespace tactus::cli {
namespace {

void print_params() {
    constexpr std::string_view kRow = "{:<36} {:>10} {:>10} {:>10} {:<4}  {}\n";
    std::cout << fmt::format(kRow, "key", "default", "min", "max", "unit", "help");
    const Settings defaults;
    for (size_t i = 0; i < param_table().size(); ++i) {
        const ParamSpec& s = param_table()[i];
        std::string range_min = fmt::format("{:g}", s.min), range_max = fmt::format("{:g}", s.max);
        if (s.kind == ParamKind::choice) range_min = range_max = "";
        std::cout << fmt::format(kRow, s.key, defaults.text_of(static_cast<P>(i)), range_min,
                                 range_max, s.unit, s.help);
    }
}

}  // namespace

void add_presets(CLI::App& app) {
    auto params = std::make_shared<bool>(false);
    CLI::App* command = app.add_subcommand("presets", "list presets (TOML files)");
    command->add_flag("--params", *params, "list every parameter a preset or --set can change");
    command->callback([params] {
        if (*params) return print_params();
        for (const auto& p : list_presets())
            std::cout << fmt::format("{:<16} {}  ({})\n", p.name, p.description, p.path.string());
    });
}

}  // namespace tactus::cli
