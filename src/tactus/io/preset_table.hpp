// A table of another file read as a preset's keys (a layout's per-output settings).
#pragma once

#include <toml++/toml.h>

#include <string_view>
#include <utility>
#include <vector>

#include "tactus/params/params.hpp"

namespace tactus {

// The parameters `table` sets, with their values, in its order: its keys and values checked as
// a preset's (io/preset.hpp); throws std::runtime_error "ORIGIN:LINE:COL: ...".
std::vector<std::pair<P, double>> preset_values(const toml::table& table, std::string_view origin);

}  // namespace tactus
