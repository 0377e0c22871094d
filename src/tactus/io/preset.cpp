#include "tactus/io/preset.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <stdexcept>

#include "tactus/core/printable.hpp"
#include "tactus/io/search_path.hpp"

namespace tactus {
namespace fs = std::filesystem;
namespace {

std::string where(std::string_view origin, const toml::source_region& region) {
    return fmt::format("{}:{}:{}", origin, region.begin.line, region.begin.column);
}

void apply_node(Settings& settings, const std::string& key, const toml::node& node,
                std::string_view origin) {
    if (const auto* table = node.as_table()) {
        for (const auto& [name, child] : *table)
            apply_node(settings,
                       key.empty() ? std::string(name.str()) : key + "." + std::string(name.str()),
                       child, origin);
        return;
    }
    if (key == "description" || key == "name") {
        if (!node.is_string())
            throw std::runtime_error(
                fmt::format("{}: '{}' must be a string", where(origin, node.source()), key));
        return;
    }
    const auto id = find_param(key);
    if (!id)
        throw std::runtime_error(fmt::format("{}: unknown key '{}' (did you mean '{}'?)",
                                             where(origin, node.source()), printable(key),
                                             nearest_param(key)));
    const ParamSpec& s = spec(*id);
    try {
        if (s.type == ParamType::toggle && node.is_boolean()) {
            settings.set(*id, *node.value<bool>() ? 1.0 : 0.0);
        } else if (!s.choices.empty()) {
            if (!node.is_string())
                throw std::invalid_argument(fmt::format("{} must be a name in quotes", key));
            settings.set_from_text(*id, *node.value<std::string>());
        } else {
            if (!node.is_number())
                throw std::invalid_argument(
                    fmt::format("{} must be a number, {}", key, range_text(s)));
            settings.set(*id, *node.value<double>());
        }
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(fmt::format("{}: {}", where(origin, node.source()), e.what()));
    }
}

std::string description_of(const fs::path& path) {
    try {
        const toml::table table = toml::parse_file(path.string());
        return table["description"].value_or(std::string{});
    } catch (const toml::parse_error&) {
        return "(does not parse)";
    }
}

}  // namespace

std::vector<fs::path> preset_search_path() {
    return search_path("TACTUS_PRESET_PATH", "presets");
}

std::vector<PresetInfo> list_presets() {
    std::vector<PresetInfo> presets;
    for (const auto& [name, path] : toml_files(preset_search_path()))
        presets.push_back({name, path, description_of(path)});
    return presets;
}

fs::path resolve_preset(std::string_view name_or_path) {
    return resolve_toml(name_or_path, preset_search_path(), "preset");
}

void apply_preset_text(Settings& settings, std::string_view toml_text, std::string_view origin) {
    toml::table table;
    try {
        table = toml::parse(toml_text, origin);
    } catch (const toml::parse_error& e) {
        throw std::runtime_error(fmt::format("{}: TOML syntax error: {}", where(origin, e.source()),
                                             printable(e.description())));
    }
    Settings candidate = settings;  // all or nothing
    apply_node(candidate, "", table, origin);
    settings = candidate;
}

void apply_preset_file(Settings& settings, const fs::path& path) {
    toml::table table;
    try {
        table = toml::parse_file(path.string());
    } catch (const toml::parse_error& e) {
        const std::string description = printable(e.description());
        if (!fs::exists(path))
            throw std::runtime_error(fmt::format("preset file '{}' not found", path.string()));
        throw std::runtime_error(fmt::format("{}: TOML syntax error: {}",
                                             where(path.string(), e.source()), description));
    }
    Settings candidate = settings;
    apply_node(candidate, "", table, path.string());
    settings = candidate;
}

void apply_assignment(Settings& settings, std::string_view assignment) {
    const size_t eq = assignment.find('=');
    if (eq == std::string_view::npos || eq == 0 || eq + 1 == assignment.size())
        throw std::invalid_argument(fmt::format(
            "--set '{}': expected key=value, e.g. envelope.decay_ms=120", printable(assignment)));
    const std::string_view key = assignment.substr(0, eq);
    const std::string_view value = assignment.substr(eq + 1);
    const auto id = find_param(key);
    if (!id)
        throw std::invalid_argument(fmt::format("--set: unknown key '{}' (did you mean '{}'?)",
                                                printable(key), nearest_param(key)));
    try {
        settings.set_from_text(*id, value);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format("--set: {}", e.what()));
    }
}

}  // namespace tactus
