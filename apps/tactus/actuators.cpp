// tactus actuators [NAME|FILE.toml]: the actuator profiles found (name, type, usable band,
// resonance, max drive, DC), or every value of one profile.
#include <fmt/format.h>

#include <iostream>

#include "commands.hpp"
#include "common.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/search_path.hpp"

namespace tactus::cli {
namespace {

std::string resonance_text(const ActuatorProfile& a) {
    if (a.resonance == ResonanceKind::none) return "none";
    return fmt::format("{:g} Hz Q {:g} ({})", a.resonance_hz, a.q,
                       a.resonance == ResonanceKind::low_pass ? "low-pass" : "band-pass");
}

void show(const ActuatorProfile& a, const std::filesystem::path& path) {
    const auto row = [](std::string_view key, const std::string& value) {
        std::cout << fmt::format("{:<24}{}\n", key, value);
    };
    row("name", a.name);
    row("file", path.string());
    row("type", std::string(type_name(a.type)));
    row("description", a.description);
    row("displacement_um",
        fmt::format("{:g} um peak at {:g} Hz, full scale", a.displacement_um, a.reference_hz));
    row("usable band", fmt::format("{:g}-{:g} Hz, {:g} dB/octave outside", a.band_low_hz,
                                   a.band_high_hz, a.rolloff_db_per_octave));
    row("resonance", resonance_text(a));
    row("max_drive", fmt::format("{:g} ({:.1f} dBFS)", a.max_drive, 20 * std::log10(a.max_drive)));
    row("dc", a.dc ? "yes: holds an offset (NPIII pressure)" : "no");
    row("rise_ms", fmt::format("{:g}", a.rise_ms));
    if (a.type == ActuatorType::erm)
        row("erm frequency",
            fmt::format("{:g}-{:g} Hz with drive", a.erm_min_drive_hz, a.erm_max_drive_hz));
    for (const auto& [hz, db] : a.points)
        row("response point", fmt::format("{:g} Hz {:+g} dB", hz, db));
}

void list() {
    std::cout << fmt::format("{:<14}{:<12}{:<14}{:<26}{:<10}{:<4}{}\n", "name", "type", "band_hz",
                             "resonance", "max_drive", "dc", "description");
    for (const auto& [name, path] : toml_files(actuator_search_path())) {
        const ActuatorProfile a = load_actuator(path);
        std::cout << fmt::format(
            "{:<14}{:<12}{:<14}{:<26}{:<10g}{:<4}{}\n", name, type_name(a.type),
            fmt::format("{:g}-{:g}", a.band_low_hz, a.band_high_hz), resonance_text(a), a.max_drive,
            a.dc ? "yes" : "no", a.description);
    }
}

}  // namespace

void add_actuators(CLI::App& app) {
    auto name = std::make_shared<std::string>();
    CLI::App* command =
        app.add_subcommand("actuators", "list the actuator profiles, or show every value of one");
    command->add_option("name", *name, "a profile's name or FILE.toml: show its values");
    command->callback([name] {
        if (name->empty()) return list();
        const std::filesystem::path path = resolve_actuator(*name);
        show(load_actuator(path), path);
    });
}

}  // namespace tactus::cli
