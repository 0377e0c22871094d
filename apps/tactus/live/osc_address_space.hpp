// The OSC address space of `tactus live`, generated from the parameter table
// (docs/architecture.md, "The parameter table"):
//   /tactus/<key> <value>                 every parameter (a number, or a choice's name)
//   /tactus/<key>                         asks for its value
//   /tactus/preset <name>                 a preset by name (no file path: untrusted input)
//   /tactus/trigger [frequency_hz amplitude]   a pulse (without arguments: the mapping's
//                                         highest frequency and amplitude)
//   /tactus/actuator/<n>/gain <dB>        actuator n's trim (n from 1)
//   /tactus/actuator/<n>/route <route>    what actuator n plays (engine/route.hpp: all, kick,
//                                         band:20-120, channel:1, ...)
//   /tactus/layout <name>                 a layout's routes and trims by name (io/layout_file.hpp;
//                                         as many outputs as actuators; no file path)
// OSC input is untrusted network input: parse_osc() validates everything against the table
// and throws std::invalid_argument with one line for anything else; nothing is applied here.
// The server answers every message to a parameter's address (set, refused or asked) with
// parameter_reply(), and a preset applied with preset_reply(), sent back to the sender.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "tactus/engine/route.hpp"
#include "tactus/params/params.hpp"

namespace tactus::live {

inline constexpr std::string_view kOscRoot = "/tactus/";

// One decoded argument: numbers ('i', 'h', 'f', 'd', and 'T'/'F' as 1/0) or text ('s', 'S').
struct OscArg {
    char type = 'f';
    double number = 0;
    std::string text;
};

struct OscMessage {
    std::string address;
    std::vector<OscArg> args;
};

struct SetParameter {
    P id;
    double value;  // checked against the table
};
struct QueryParameter {
    P id;
};
struct LoadPreset {
    std::string name;
};
struct TriggerPulse {
    bool with_values = false;  // false: the current mapping's highest frequency and amplitude
    double frequency_hz = 0, amplitude = 0;
};
struct ActuatorGain {
    int actuator;  // from 0
    double gain_db;
};
struct ActuatorRoute {
    int actuator;  // from 0
    Route route;
};
struct LoadLayout {
    std::string name;
};
using OscCommand = std::variant<SetParameter, QueryParameter, LoadPreset, TriggerPulse,
                                ActuatorGain, ActuatorRoute, LoadLayout>;

// `actuators`: the engine's actuator outputs. Throws std::invalid_argument, one line naming the
// address.
OscCommand parse_osc(const OscMessage& message, int actuators);

// The parameter an address names (refused messages included), if any.
std::optional<P> parameter_of(std::string_view address);
// /tactus/<key> with the value `settings` hold: a choice's name ('s'), else a number ('f').
OscMessage parameter_reply(P id, const Settings& settings);
// /tactus/preset <name>: the preset applied.
OscMessage preset_reply(const std::string& name);

// Every address, for help texts: one line each with the argument and its range.
std::vector<std::string> osc_address_lines();

}  // namespace tactus::live
