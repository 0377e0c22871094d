// The parameter table as JSON, for the studio's page: the page draws one control per row from
// it (type, unit, range, curve, default, help, choices, group); nothing else describes a
// parameter.
#pragma once

#include <nlohmann/json.hpp>

namespace tactus::cli {

// [{key, id, group, type, unit, min, max, default, default_text, curve, change, help,
//   choices}], in table order; group: the key up to its last dot (the preset's table).
nlohmann::json params_json();

}  // namespace tactus::cli
