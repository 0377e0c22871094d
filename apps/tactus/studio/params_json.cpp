#include "params_json.hpp"

#include "tactus/params/params.hpp"

namespace tactus::cli {

nlohmann::json params_json() {
    const Settings defaults;
    nlohmann::json rows = nlohmann::json::array();
    for (const ParamSpec& s : param_table()) {
        const std::string key(s.key);
        nlohmann::json choices = nlohmann::json::array();
        for (const auto& c : s.choices) choices.push_back(std::string(c));
        rows.push_back({{"key", key},
                        {"id", s.id},
                        {"group", key.substr(0, key.rfind('.'))},
                        {"type", std::string(kParamTypeNames[static_cast<int>(s.type)])},
                        {"unit", std::string(s.unit)},
                        {"min", s.min},
                        {"max", s.max},
                        {"default", defaults[s.param]},
                        {"default_text", defaults.text_of(s.param)},
                        {"curve", s.curve == ParamCurve::log ? "log" : "lin"},
                        {"change", s.change == ParamChange::live ? "live" : "structural"},
                        {"help", std::string(s.help)},
                        {"choices", choices}});
    }
    return rows;
}

}  // namespace tactus::cli
