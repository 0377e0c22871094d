#include "tactus/io/layout_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <stdexcept>

#include "tactus/engine/engine.hpp"
#include "tactus/io/preset_table.hpp"
#include "tactus/io/search_path.hpp"
#include "tactus/io/toml_reader.hpp"

namespace tactus {
namespace fs = std::filesystem;
namespace {

constexpr int kMaxChannels = 1024;  // libsndfile's SF_MAX_CHANNELS

// A channel number from 1 in a file, counted from 0.
int channel_of(TomlReader& reader, const toml::node& node, std::string_view key) {
    const auto value = node.value<int64_t>();
    if (!node.is_integer() || *value < 1 || *value > kMaxChannels)
        reader.fail(&node, key, fmt::format("must be a channel number from 1 to {}", kMaxChannels));
    return static_cast<int>(*value - 1);
}

LayoutOutput read_output(const toml::table& table, std::string_view origin, size_t index) {
    TomlReader reader(table, origin, fmt::format("output[{}].", index + 1));
    LayoutOutput o;
    o.name = reader.text("name", fmt::format("output{}", index + 1));
    const bool plain =
        !o.name.empty() && o.name.size() <= 64 &&
        std::all_of(o.name.begin(), o.name.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
        });
    if (!plain)
        reader.fail(reader.get("name"), "name",
                    "1-64 letters, digits, '-' or '_' (it names files)");
    o.channel = -1;
    if (const toml::node* node = reader.get("channel"))
        o.channel = channel_of(reader, *node, "channel");
    o.actuator = reader.text("actuator", "");
    const std::string route = reader.text("route", "all");
    try {
        o.output.route = Route::parse(route);
    } catch (const std::invalid_argument& e) {
        reader.fail(reader.get("route"), "route", e.what());
    }
    o.output.gain_db = reader.number("gain_db", ActuatorOutput::kMinGainDb, 0, 0);
    o.output.delay_ms = reader.number("delay_ms", 0, ActuatorOutput::kMaxDelayMs, 0);
    if (const toml::node* node = reader.get("set")) {
        if (!node->is_table()) reader.fail(node, "set", "must be a table [output.set]");
        o.output.overlay = preset_values(*node->as_table(), origin);
        try {
            check_overlay(o.output.overlay);
        } catch (const std::invalid_argument& e) {
            reader.fail(node, "set", e.what());
        }
    }
    reader.reject_unknown_keys();
    return o;
}

}  // namespace

std::vector<ActuatorOutput> Layout::actuator_outputs(const ProfileLoader& load_profile) const {
    std::vector<ActuatorOutput> engine_outputs(outputs.size());
    std::map<std::string, ActuatorProfile> loaded;
    for (size_t k = 0; k < outputs.size(); ++k) {
        const LayoutOutput& o = outputs[k];
        engine_outputs[k] = o.output;
        if (o.actuator.empty()) continue;
        try {
            if (!loaded.contains(o.actuator)) loaded.emplace(o.actuator, load_profile(o.actuator));
        } catch (const std::exception& e) {
            throw std::runtime_error(
                fmt::format("layout {}: output {}: {}", name, o.name, e.what()));
        }
        engine_outputs[k].profile = loaded.at(o.actuator);
    }
    return engine_outputs;
}

std::vector<fs::path> layout_search_path() {
    return search_path("TACTUS_LAYOUT_PATH", "layouts");
}

fs::path resolve_layout(std::string_view name_or_path) {
    return resolve_toml(name_or_path, layout_search_path(), "layout");
}

Layout parse_layout(std::string_view toml_text, std::string_view origin) {
    const toml::table table = parse_toml(toml_text, origin);
    TomlReader top(table, origin, "");
    Layout layout;
    layout.name = fs::path(origin).stem().string();
    layout.description = top.text("description", "");
    const toml::node* outputs = top.get("output");
    const toml::array* array = outputs ? outputs->as_array() : nullptr;
    if (!array || array->empty() || !array->is_array_of_tables())
        top.fail(outputs, "output", "a layout needs one [[output]] table per actuator");
    if (array->size() > static_cast<size_t>(Engine::kMaxActuators))
        top.fail(outputs, "output", fmt::format("at most {} outputs", Engine::kMaxActuators));
    if (const toml::node* sound = top.get("sound")) {
        const toml::array* channels = sound->as_array();
        if (!channels) top.fail(sound, "sound", "must be a list of channel numbers, [1, 2]");
        for (const toml::node& c : *channels)
            layout.sound_channels.push_back(channel_of(top, c, "sound"));
    }
    std::vector<int> taken = layout.sound_channels;
    for (size_t k = 0; k < array->size(); ++k) {
        const toml::table& t = *(*array)[k].as_table();
        LayoutOutput o = read_output(t, origin, k);
        if (std::any_of(layout.outputs.begin(), layout.outputs.end(),
                        [&](const LayoutOutput& other) { return other.name == o.name; }))
            top.fail(t.get("name"), fmt::format("output[{}].name", k + 1),
                     fmt::format("'{}' names an earlier output too", o.name));
        if (o.channel < 0) {  // the first free channel
            o.channel = 0;
            while (std::find(taken.begin(), taken.end(), o.channel) != taken.end()) ++o.channel;
        } else if (std::find(taken.begin(), taken.end(), o.channel) != taken.end()) {
            top.fail(t.get("channel"), fmt::format("output[{}].channel", k + 1),
                     fmt::format("channel {} is taken by the sound or an earlier output",
                                 o.channel + 1));
        }
        taken.push_back(o.channel);
        layout.outputs.push_back(std::move(o));
    }
    const int used = *std::max_element(taken.begin(), taken.end()) + 1;
    layout.channels = used;
    if (const toml::node* node = top.get("channels")) {
        const auto value = node->value<int64_t>();
        if (!node->is_integer() || *value < used || *value > kMaxChannels)
            top.fail(node, "channels",
                     fmt::format("must be a whole number from {} (the channels used) to {}", used,
                                 kMaxChannels));
        layout.channels = static_cast<int>(*value);
    }
    top.reject_unknown_keys();
    return layout;
}

Layout load_layout(const fs::path& path) {
    return parse_layout(toml_file_text(path, "layout"), path.string());
}

}  // namespace tactus
