// Presets: TOML files whose keys are the parameter table's dotted names, e.g.
//   [mapping.frequency]
//   out_max = 320
// plus `description`. `--set key=value` uses the same names. Everything is validated before
// any audio is processed; errors are one line naming the file, line or key.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tactus/params/params.hpp"

namespace tactus {

struct PresetInfo {
    std::string name;
    std::filesystem::path path;
    std::string description;
};

// Directories searched for presets by name (io/search_path.hpp).
std::vector<std::filesystem::path> preset_search_path();
std::vector<PresetInfo> list_presets();

// A name ("tfd") or a path to a .toml file.
std::filesystem::path resolve_preset(std::string_view name_or_path);

// Applies a preset file on top of `settings`; throws std::runtime_error with file:line context.
void apply_preset_file(Settings& settings, const std::filesystem::path& path);
// Same for TOML text (`origin` names it in messages).
void apply_preset_text(Settings& settings, std::string_view toml_text, std::string_view origin);
// Applies one "key=value" assignment; throws std::invalid_argument naming the key.
void apply_assignment(Settings& settings, std::string_view assignment);

}  // namespace tactus
