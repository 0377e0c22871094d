#include "osc_address_space.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

#include "tactus/core/printable.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus::live {
namespace {

constexpr size_t kMaxNameBytes = 4096;  // a preset name or path

[[noreturn]] void refuse(const OscMessage& m, const std::string& why) {
    throw std::invalid_argument(
        fmt::format("osc {}: {}", printable(std::string_view(m.address).substr(0, 200)), why));
}

bool is_number(const OscArg& a) {
    return a.type == 'i' || a.type == 'h' || a.type == 'f' || a.type == 'd' || a.type == 'T' ||
           a.type == 'F';
}
bool is_text(const OscArg& a) {
    return a.type == 's' || a.type == 'S';
}

double number_arg(const OscMessage& m, size_t i, std::string_view what) {
    if (i >= m.args.size() || !is_number(m.args[i]))
        refuse(m, fmt::format("argument {} ({}) must be a number", i + 1, what));
    const double v = m.args[i].number;
    if (!std::isfinite(v)) refuse(m, fmt::format("{} is not a finite number", what));
    return v;
}

void expect_args(const OscMessage& m, size_t low, size_t high, std::string_view usage) {
    if (m.args.size() < low || m.args.size() > high)
        refuse(m, fmt::format("takes {} ({} given)", usage, m.args.size()));
}

OscCommand parse_parameter(const OscMessage& m, std::string_view key) {
    const std::optional<P> id = find_param(key);
    if (!id)
        refuse(m,
               fmt::format("unknown address (did you mean {}{}?)", kOscRoot, nearest_param(key)));
    expect_args(m, 0, 1, "one value (none: asks for it)");
    if (m.args.empty()) return QueryParameter{*id};
    Settings checked;  // Settings validates against the table, naming the key
    try {
        const OscArg& a = m.args[0];
        if (is_text(a)) {
            if (a.text.size() > kMaxNameBytes) refuse(m, "the text is too long");
            checked.set_from_text(*id, a.text);
        } else if (is_number(a)) {
            checked.set(*id, a.number);
        } else {
            refuse(m, fmt::format("the value must be a number or a name, not type '{}'",
                                  printable(std::string_view(&a.type, 1))));
        }
    } catch (const std::invalid_argument& e) {
        if (std::string_view(e.what()).starts_with("osc ")) throw;
        refuse(m, e.what());
    }
    return SetParameter{*id, checked[*id]};
}

OscCommand parse_actuator(const OscMessage& m, std::string_view rest, int actuators) {
    // rest: "<n>/gain" or "<n>/route"
    const size_t slash = rest.find('/');
    const std::string_view what = slash == std::string_view::npos ? "" : rest.substr(slash + 1);
    if (what != "gain" && what != "route")
        refuse(m, fmt::format("unknown address (an actuator's are {0}actuator/<n>/gain and "
                              "{0}actuator/<n>/route)",
                              kOscRoot));
    int n = 0;
    const std::string_view digits = rest.substr(0, slash);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (error != std::errc() || end != digits.data() + digits.size() || n < 1 || n > actuators)
        refuse(m,
               fmt::format("actuator '{}' does not exist: 1 to {}", printable(digits), actuators));
    if (what == "route") {
        expect_args(m, 1, 1, "one route");
        if (!is_text(m.args[0]))
            refuse(m, "the route must be a string (all, kick, band:20-120, ...)");
        try {
            return ActuatorRoute{n - 1, Route::parse(m.args[0].text)};
        } catch (const std::invalid_argument& e) {
            refuse(m, e.what());
        }
    }
    expect_args(m, 1, 1, "one gain in dB");
    const double gain_db = number_arg(m, 0, "gain_db");
    try {
        ActuatorOutput::check_gain_db(gain_db);
    } catch (const std::invalid_argument& e) {
        refuse(m, e.what());
    }
    return ActuatorGain{n - 1, gain_db};
}

// A preset's or a layout's name: a message from the network reads no file it names.
std::string plain_name(const OscMessage& m, std::string_view kind, std::string_view listing) {
    expect_args(m, 1, 1, fmt::format("one {} name", kind));
    if (!is_text(m.args[0])) refuse(m, fmt::format("the {} name must be a string", kind));
    const std::string& name = m.args[0].text;
    const bool plain = !name.empty() && name.size() <= kMaxNameBytes && name[0] != '.' &&
                       !name.ends_with(".toml") &&
                       name.find_first_not_of(
                           "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTU"
                           "VWXYZ0123456789_-.") == std::string::npos;
    if (!plain)
        refuse(m, fmt::format("'{}' is not a {} name (see {}; files are not loaded over OSC)",
                              printable(std::string_view(name).substr(0, 200)), kind, listing));
    return name;
}

}  // namespace

OscCommand parse_osc(const OscMessage& m, int actuators) {
    const std::string_view address = m.address;
    if (!address.starts_with(kOscRoot))
        refuse(m, fmt::format("unknown address (tactus listens under {})", kOscRoot));
    const std::string_view rest = address.substr(kOscRoot.size());
    if (rest == "preset") return LoadPreset{plain_name(m, "preset", "`tactus presets`")};
    if (rest == "layout") return LoadLayout{plain_name(m, "layout", "the layouts folder")};
    if (rest == "trigger") {
        expect_args(m, 0, 2, "no arguments, or frequency_hz and amplitude");
        if (m.args.size() == 1) refuse(m, "takes no arguments, or frequency_hz and amplitude");
        if (m.args.empty()) return TriggerPulse{};
        const double f = number_arg(m, 0, "frequency_hz"), a = number_arg(m, 1, "amplitude");
        try {
            Engine::check_trigger(f, a);
        } catch (const std::invalid_argument& e) {
            refuse(m, e.what());
        }
        return TriggerPulse{true, f, a};
    }
    if (rest.starts_with("actuator/")) return parse_actuator(m, rest.substr(9), actuators);
    return parse_parameter(m, rest);
}

std::optional<P> parameter_of(std::string_view address) {
    if (!address.starts_with(kOscRoot)) return std::nullopt;
    return find_param(address.substr(kOscRoot.size()));
}

OscMessage parameter_reply(P id, const Settings& settings) {
    OscMessage m{fmt::format("{}{}", kOscRoot, spec(id).key), {}};
    if (spec(id).choices.empty())
        m.args.push_back(OscArg{'f', settings[id], ""});
    else
        m.args.push_back(OscArg{'s', 0, settings.text_of(id)});
    return m;
}

OscMessage preset_reply(const std::string& name) {
    return {fmt::format("{}preset", kOscRoot), {OscArg{'s', 0, name}}};
}

std::vector<std::string> osc_address_lines() {
    std::vector<std::string> lines;
    for (const ParamSpec& s : param_table()) {
        const std::string argument =
            s.choices.empty() ? range_text(s) : fmt::format("{}", fmt::join(s.choices, "|"));
        lines.push_back(fmt::format("{}{} [<{}>]", kOscRoot, s.key, argument));
    }
    lines.push_back(fmt::format("{}preset <name>", kOscRoot));
    lines.push_back(fmt::format("{}trigger [frequency_hz amplitude]", kOscRoot));
    lines.push_back(
        fmt::format("{}actuator/<n>/gain <{} to 0 dB>", kOscRoot, ActuatorOutput::kMinGainDb));
    lines.push_back(
        fmt::format("{}actuator/<n>/route <all|kick+snare|band:LOW-HIGH|channel:N>", kOscRoot));
    lines.push_back(fmt::format("{}layout <name>", kOscRoot));
    return lines;
}

}  // namespace tactus::live
