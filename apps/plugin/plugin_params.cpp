#include "plugin_params.hpp"

#include <algorithm>
#include <cmath>

namespace tactus::plugin {

uint32_t parameter_count() {
    uint32_t largest = 0;
    for (const ParamSpec& s : param_table()) largest = std::max(largest, s.id);
    return largest + 1;
}

std::optional<P> param_at(uint32_t index) {
    if (index == kBypassIndex) return std::nullopt;
    return find_param(index);
}

double from_host(const ParamSpec& spec, float value) noexcept {
    double v = std::isfinite(value) ? static_cast<double>(value) : spec.default_value;
    if (spec.type != ParamType::real) v = std::round(v);
    return std::clamp(v, spec.min, spec.max);
}

}  // namespace tactus::plugin
