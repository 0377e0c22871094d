#include "tactus/actuator/warnings.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tactus/core/units.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {

std::vector<std::string> actuator_warnings(const ActuatorProfile& a, const Settings& s) {
    std::vector<std::string> w;
    const auto say = [&](std::string text) { w.push_back(fmt::format("{}: {}", a.name, text)); };
    const std::string band =
        fmt::format("its usable band is {:g}-{:g} Hz", a.band_low_hz, a.band_high_hz);
    const double low_hz = s[P::frequency_out_min], high_hz = s[P::frequency_out_max];
    if (std::min(low_hz, high_hz) < a.band_low_hz)
        say(fmt::format("the preset asks for {:g} Hz (mapping.frequency) but {}",
                        std::min(low_hz, high_hz), band));
    if (std::max(low_hz, high_hz) > a.band_high_hz)
        say(fmt::format("the preset asks for {:g} Hz (mapping.frequency) but {}",
                        std::max(low_hz, high_hz), band));
    const double pressure_hz = perception::info(perception::Channel::NPIII).range_high_hz;
    if (!a.dc && s[P::post_band_low_hz] < pressure_hz)
        say(
            fmt::format("post.band_low_hz = {:g} Hz passes pressure (NPIII, below {:g} Hz) but the "
                        "actuator cannot hold an offset (dc = false)",
                        s[P::post_band_low_hz], pressure_hz));
    if (!a.dc && s[P::pressure_weight] > 0)
        say(
            fmt::format("pressure.weight = {:g} asks for NPIII pressure but the actuator cannot "
                        "hold an offset (dc = false): the pressure is off",
                        s[P::pressure_weight]));
    if (a.type == ActuatorType::erm && low_hz != high_hz)
        say(
            fmt::format("an ERM's frequency follows its drive ({:g}-{:g} Hz): the preset's "
                        "frequency mapping is not reproduced",
                        a.erm_min_drive_hz, a.erm_max_drive_hz));
    if (a.rise_ms > s[P::envelope_attack_ms])
        say(fmt::format("rises in {:g} ms: envelope.attack_ms = {:g} ms is softened", a.rise_ms,
                        s[P::envelope_attack_ms]));
    if (s[P::post_ceiling_db] > gain_to_db(a.max_drive))
        say(
            fmt::format("max drive {:.1f} dBFS: the output ceiling (post.ceiling_db = {:g}) is "
                        "lowered to it",
                        gain_to_db(a.max_drive), s[P::post_ceiling_db]));
    return w;
}

}  // namespace tactus
