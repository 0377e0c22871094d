#include "host_parameters.hpp"

#include "plugin_params.hpp"

namespace tactus::plugin {

HostParameters::HostParameters() {
    for (const ParamSpec& s : param_table()) {
        values_[static_cast<size_t>(s.param)].store(s.default_value);
        changed_[static_cast<size_t>(s.param)].store(false);
    }
}

void HostParameters::set_from_host(P id, float value) noexcept {
    if (static_cast<float>(this->value(id)) == value) return;  // an echo of the value held
    set_exact(id, from_host(spec(id), value));
}

void HostParameters::set_exact(P id, double value) noexcept {
    const auto i = static_cast<size_t>(id);
    values_[i].store(value, std::memory_order_release);
    changed_[i].store(true, std::memory_order_release);
    any_.store(true, std::memory_order_release);
}

void HostParameters::set_all(const Settings& settings) noexcept {
    for (const ParamSpec& s : param_table()) set_exact(s.param, settings[s.param]);
}

Settings HostParameters::settings() const noexcept {
    Settings settings;
    for (const ParamSpec& s : param_table()) settings.assign(s.param, value(s.param));
    return settings;
}

}  // namespace tactus::plugin
