#include "tactus/io/preset.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "tactus/core/printable.hpp"
#include "tactus/io/preset_table.hpp"
#include "tactus/io/search_path.hpp"

namespace tactus {
namespace fs = std::filesystem;
namespace {

std::string where(std::string_view origin, const toml::source_region& region) {
    return fmt::format("{}:{}:{}", origin, region.begin.line, region.begin.column);
}

// The file's `format` (1 when absent); refuses a format newer than this library reads.
int format_of(const toml::table& table, std::string_view origin) {
    const toml::node* node = table.get("format");
    if (!node) return 1;
    const auto format = node->value<int64_t>();
    if (!node->is_integer() || *format < 1)
        throw std::runtime_error(fmt::format("{}: 'format' must be a whole number from 1",
                                             where(origin, node->source())));
    if (*format > kPresetFormat)
        throw std::runtime_error(
            fmt::format("{}: format {} is newer than this tactus reads ({}): update tactus",
                        where(origin, node->source()), *format, kPresetFormat));
    return static_cast<int>(*format);
}

// `set`, when given, receives each parameter set, in the table's order.
void apply_node(Settings& settings, const std::string& path, const toml::node& node, int format,
                std::string_view origin, std::vector<P>* set = nullptr) {
    if (const auto* table = node.as_table()) {
        for (const auto& [name, child] : *table)
            apply_node(
                settings,
                path.empty() ? std::string(name.str()) : path + "." + std::string(name.str()),
                child, format, origin, set);
        return;
    }
    if (path == "format") return;  // format_of() read it
    if (path == "description" || path == "name") {
        if (!node.is_string())
            throw std::runtime_error(
                fmt::format("{}: '{}' must be a string", where(origin, node.source()), path));
        return;
    }
    const std::string key(current_key(path, format));
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
    if (set) set->push_back(*id);
}

// One value as TOML: a toggle as a boolean, a choice by name, a real in its shortest form that
// reads back as the same double.
std::string toml_value(const Settings& settings, const ParamSpec& s) {
    const double v = settings[s.param];
    switch (s.type) {
        case ParamType::toggle:
            return v != 0 ? "true" : "false";
        case ParamType::choice:
            return fmt::format("\"{}\"", s.choices[static_cast<size_t>(v)]);
        case ParamType::integer:
            return fmt::format("{}", static_cast<int64_t>(v));
        case ParamType::real:
            break;
    }
    std::string text = fmt::format("{}", v);
    if (text.find_first_of(".e") == std::string::npos) text += ".0";  // a TOML float: -0.0 stays
    return text;
}

// A parsed preset on top of `settings`: all or nothing.
void apply_table(Settings& settings, const toml::table& table, std::string_view origin) {
    Settings candidate = settings;
    apply_node(candidate, "", table, format_of(table, origin), origin);
    settings = candidate;
}

}  // namespace

std::vector<std::pair<P, double>> preset_values(const toml::table& table, std::string_view origin) {
    Settings settings;
    std::vector<P> set;
    apply_node(settings, "", table, kPresetFormat, origin, &set);
    std::vector<std::pair<P, double>> values(set.size());
    for (size_t k = 0; k < set.size(); ++k) values[k] = {set[k], settings[set[k]]};
    return values;
}

namespace {

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
    apply_table(settings, table, origin);
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
    apply_table(settings, table, path.string());
}

std::string_view current_key(std::string_view key, int format, std::span<const KeyRename> renames) {
    for (const KeyRename& r : renames)
        if (format < r.since && key == r.old_key) key = r.new_key;
    return key;
}

std::string preset_text(const Settings& settings, std::string_view description) {
    std::ostringstream quoted;
    quoted << toml::value<std::string>(std::string(description));
    std::string text = fmt::format(
        "# tactus preset: every parameter (`tactus presets --params` describes each)\n"
        "format = {}\ndescription = {}\n",
        kPresetFormat, quoted.str());
    // One table per first part of the keys, in the order the parameter table first names it.
    std::vector<std::string_view> groups;
    for (const ParamSpec& s : param_table()) {
        const std::string_view group = s.key.substr(0, s.key.find('.'));
        if (std::find(groups.begin(), groups.end(), group) == groups.end()) groups.push_back(group);
    }
    for (const std::string_view group : groups) {
        text += fmt::format("\n[{}]\n", group);
        for (const ParamSpec& s : param_table())
            if (s.key.substr(0, s.key.find('.')) == group)
                text += fmt::format("{} = {}\n", s.key.substr(group.size() + 1),
                                    toml_value(settings, s));
    }
    return text;
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
