// Presets: TOML files whose keys are the parameter table's dotted names, e.g.
//   [mapping.frequency]
//   out_max = 320
// plus `description` and `format`. `--set key=value` uses the same names. Everything is
// validated before any audio is processed; errors are one line naming the file, line or key.
// A preset is also the engine's state: preset_text() writes every parameter, and a front end
// (a plugin's session, a Pd patch) stores that text and loads it back bit for bit.
#pragma once

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tactus/params/params.hpp"

namespace tactus {

// The preset format written, and the newest read. A file without `format` is format 1.
inline constexpr int kPresetFormat = 1;

// A key renamed in format `since`: in files of an older format, `old_key` means `new_key`.
struct KeyRename {
    int since;
    std::string_view old_key, new_key;
};
// Every rename so far, oldest first (format 1 is the first format: none yet). A rename bumps
// kPresetFormat and adds its line here; the key keeps its id (params/param_ids.txt).
inline constexpr std::array<KeyRename, 0> kKeyRenames{};
// The key that `key` in a file of `format` means today.
std::string_view current_key(std::string_view key, int format,
                             std::span<const KeyRename> renames = kKeyRenames);

struct PresetInfo {
    std::string name;
    std::filesystem::path path;
    std::string description;
};

// Directories searched for presets by name (io/search_path.hpp).
std::vector<std::filesystem::path> preset_search_path();
std::vector<PresetInfo> list_presets();

// The preset every front end starts from: the parameter table's defaults (presets/music.toml
// restates the mapping's, the envelope's and the brightness's with why; the paper's own mapping
// is presets/tfd.toml).
inline constexpr const char* kDefaultPreset = "music";

// A name ("tfd") or a path to a .toml file.
std::filesystem::path resolve_preset(std::string_view name_or_path);

// Applies a preset file on top of `settings`; throws std::runtime_error with file:line context.
void apply_preset_file(Settings& settings, const std::filesystem::path& path);
// Same for TOML text (`origin` names it in messages).
void apply_preset_text(Settings& settings, std::string_view toml_text, std::string_view origin);
// Every parameter of `settings` as preset text (format kPresetFormat, grouped by the keys'
// first part, reals in the shortest form that reads back as the same double): applied to any
// Settings it gives `settings` bit for bit.
std::string preset_text(const Settings& settings, std::string_view description);

// Applies one "key=value" assignment; throws std::invalid_argument naming the key.
void apply_assignment(Settings& settings, std::string_view assignment);

}  // namespace tactus
