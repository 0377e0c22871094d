// The four psychophysical channels of mechanoreception in glabrous skin: the paper's Table 1
// (section 3.5, adapted from Bolanowski, Gescheider, Verrillo & Checkosky 1988, JASA 84:1680).
// Channels are independent (Gescheider et al. 2004, Behav Brain Res 148:35): each has its own
// threshold curve, and the whole system detects at the lowest of them.
#pragma once

#include <array>
#include <string_view>

namespace tactus::perception {

enum class Channel { P, NPI, NPII, NPIII };
enum class ResponseShape { u_shape, flat };

struct ChannelInfo {
    Channel channel;
    std::string_view name;               // "P", "NPI", ...
    std::string_view full_name;          // "Pacinian", ...
    std::string_view fibre;              // physiological type: FAII, FAI, SAII, SAI
    std::string_view receptor;           // putative receptor structure
    double innervation_per_cm2;          // fibre innervation density, human fingerpad
    std::string_view sensation;          // subjective sensation when stimulated alone
    double range_low_hz, range_high_hz;  // frequency range
    double best_low_hz, best_high_hz;    // prime sensitivity range (lowest thresholds)
    ResponseShape shape;                 // shape of the frequency response function
    std::string_view shape_note;         // e.g. NPI's notch at 30 Hz (Table 1, note 3)
};

inline constexpr std::array<ChannelInfo, 4> kChannels = {{
    {Channel::P, "P", "Pacinian", "FAII", "Pacinian", 21, "vibration", 40, 500, 250, 300,
     ResponseShape::u_shape, ""},
    {Channel::NPI, "NPI", "Non-Pacinian I", "FAI", "Meissner", 140, "flutter", 2, 40, 25, 40,
     ResponseShape::flat, "notch at 30 Hz"},
    {Channel::NPII, "NPII", "Non-Pacinian II", "SAII", "Ruffini", 49, "unknown", 100, 500, 150, 400,
     ResponseShape::u_shape, ""},
    {Channel::NPIII, "NPIII", "Non-Pacinian III", "SAI", "Merkel", 70, "pressure", 0.4, 3.0, 0.4,
     1.0, ResponseShape::flat, ""},
}};

constexpr const ChannelInfo& info(Channel c) {
    return kChannels[static_cast<int>(c)];
}

}  // namespace tactus::perception
