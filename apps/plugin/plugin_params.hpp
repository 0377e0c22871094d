// The plugin's parameters, generated from the one parameter table (src/tactus/params): a host
// parameter's index is the table row's stable id, so automation and sessions never depend on
// the table's order (CLAP and VST3 take the index as the parameter id; LV2 keys ports by
// symbol, the dotted key with '_' for '.'). Index 0, an id the table never gives, is the
// plugin's own bypass. Format-neutral: no DPF here.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "tactus/params/params.hpp"

namespace tactus::plugin {

inline constexpr uint32_t kBypassIndex = 0;

// Host parameters: the bypass plus one per stable id up to the largest (an id no longer in
// the table stays a hidden placeholder, so no later id moves).
uint32_t parameter_count();
// The table row behind a host parameter; none for the bypass or a retired id.
std::optional<P> param_at(uint32_t index);
// A host's value as the table takes it: clamped to the range, whole numbers for integer,
// toggle and choice rows. Any thread, never allocates.
double from_host(const ParamSpec& spec, float value) noexcept;

}  // namespace tactus::plugin
