// tactus presets [--params]: the presets found, or the parameter table they draw on.
#include <fmt/format.h>

#include <iostream>

#include "commands.hpp"
#include "tactus/params/params.hpp"
#include "tactus/io/preset.hpp"

namespace tactus::cli {
namespace {

void print_params() {
    constexpr std::string_view kRow = "{:>3} {:<36} {:<7} {:>10} {:>10} {:>10} {:<4} {:<10}  {}\n";
    constexpr std::string_view kTypes[] = {"real", "integer", "toggle", "choice"};
    std::cout << fmt::format(kRow, "id", "key", "type", "default", "min", "max", "unit", "change",
                             "help");
    const Settings defaults;
    for (const ParamSpec& s : param_table()) {
        std::string range_min = fmt::format("{:g}", s.min), range_max = fmt::format("{:g}", s.max);
        if (!s.choices.empty()) range_min = range_max = "";
        const std::string change = s.change == ParamChange::structural ? "structural"
                                   : s.smoothing_ms > 0 ? fmt::format("{:g} ms", s.smoothing_ms)
                                                        : "live";
        std::cout << fmt::format(kRow, s.id, s.key, kTypes[static_cast<int>(s.type)],
                                 defaults.text_of(s.param), range_min, range_max, s.unit, change,
                                 s.help);
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
