#include "tactus/io/actuator_file.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "tactus/core/printable.hpp"
#include "tactus/io/search_path.hpp"
#include "tactus/io/toml_reader.hpp"

namespace tactus {

// [response] kind, in the order of ResonanceKind.
constexpr std::string_view kResonanceKinds[] = {"none", "low-pass", "band-pass"};
namespace fs = std::filesystem;

std::vector<fs::path> actuator_search_path() {
    return search_path("TACTUS_ACTUATOR_PATH", "actuators");
}

fs::path resolve_actuator(std::string_view name_or_path) {
    return resolve_toml(name_or_path, actuator_search_path(), "actuator");
}

ActuatorProfile parse_actuator(std::string_view toml_text, std::string_view origin) {
    const toml::table table = parse_toml(toml_text, origin);
    ActuatorProfile a;
    TomlReader top(table, origin, "");
    a.name = top.text("name", fs::path(origin).stem().string());
    a.description = top.text("description", "");
    a.type = static_cast<ActuatorType>(top.choice("type", kActuatorTypeNames, 0));
    a.displacement_um = top.number("displacement_um", 1e-3, 1e4, 0, true);
    a.reference_hz = top.number("reference_hz", 0.1, 20000, 0, true);
    a.max_drive = top.number("max_drive", 1e-3, 1, 1);
    if (const toml::node* dc = top.get("dc")) {
        if (!dc->is_boolean()) top.fail(dc, "dc", "must be true or false");
        a.dc = *dc->value<bool>();
    }
    a.band_low_hz = top.number("band_low_hz", 0, 20000, 0, true);
    a.band_high_hz = top.number("band_high_hz", 0.1, 20000, 0, true);
    if (a.band_high_hz <= a.band_low_hz)
        top.fail(top.get("band_high_hz"), "band_high_hz", "must be above band_low_hz");
    if (!a.dc && a.band_low_hz <= 0)
        top.fail(top.get("band_low_hz"), "band_low_hz", "must be above 0 without dc = true");
    a.rolloff_db_per_octave = top.number("rolloff_db_per_octave", 0, 48, 12);
    a.rise_ms = top.number("rise_ms", 0, 1000, 0);

    if (const toml::node* node = top.get("response")) {
        if (!node->is_table()) top.fail(node, "response", "must be a table [response]");
        TomlReader response(*node->as_table(), origin, "response.");
        a.resonance = static_cast<ResonanceKind>(response.choice("kind", kResonanceKinds, 0));
        if (a.resonance != ResonanceKind::none) {
            a.resonance_hz = response.number("resonance_hz", 0.1, 20000, 0, true);
            a.q = response.number("q", 0.1, 100, 1);
        }
        if (const toml::node* pts = response.get("points")) {
            const toml::array* array = pts->as_array();
            if (!array) response.fail(pts, "points", "must be an array of [Hz, dB] pairs");
            for (const toml::node& p : *array) {
                const toml::array* pair = p.as_array();
                if (!pair || pair->size() != 2 || !(*pair)[0].is_number() ||
                    !(*pair)[1].is_number())
                    response.fail(&p, "points", "each point must be [Hz, dB]");
                const double f = *(*pair)[0].value<double>(), db = *(*pair)[1].value<double>();
                if (!(f > 0 && f <= 20000) || !(std::abs(db) <= 100))
                    response.fail(&p, "points", "Hz must be in (0, 20000], dB in [-100, 100]");
                if (!a.points.empty() && f <= a.points.back().first)
                    response.fail(&p, "points", "frequencies must increase");
                a.points.emplace_back(f, db);
            }
        }
        response.reject_unknown_keys();
    }
    if (a.resonance == ResonanceKind::band_pass && a.dc)
        top.fail(top.get("dc"), "dc", "a band-pass (resonant) actuator cannot hold an offset");
    if (const toml::node* node = top.get("erm")) {
        if (!node->is_table()) top.fail(node, "erm", "must be a table [erm]");
        TomlReader erm(*node->as_table(), origin, "erm.");
        a.erm_min_drive_hz = erm.number("frequency_at_min_drive_hz", 1, 1000, 0, true);
        a.erm_max_drive_hz = erm.number("frequency_at_max_drive_hz", 1, 1000, 0, true);
        erm.reject_unknown_keys();
    }
    if (a.type == ActuatorType::erm && a.erm_max_drive_hz <= 0)
        top.fail(nullptr, "erm", "an ERM profile needs [erm] frequency_at_min/max_drive_hz");
    top.reject_unknown_keys();
    return a;
}

ActuatorProfile load_actuator(const fs::path& path) {
    return parse_actuator(toml_file_text(path, "actuator"), path.string());
}

std::string actuator_text(const ActuatorProfile& a, std::string_view comment) {
    const auto quoted = [](std::string_view text) {  // as toml++ writes a string
        std::ostringstream out;
        out << toml::value<std::string>(std::string(text));
        return out.str();
    };
    std::string t;
    std::string_view rest = comment;
    while (!rest.empty()) {
        const size_t end = rest.find('\n');
        t += fmt::format("# {}\n", rest.substr(0, end));
        rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
    }
    t += fmt::format("name = {}\ntype = \"{}\"\ndescription = {}\n", quoted(a.name),
                     type_name(a.type), quoted(a.description));
    t += fmt::format("displacement_um = {}\nreference_hz = {}\nmax_drive = {}\ndc = {}\n",
                     a.displacement_um, a.reference_hz, a.max_drive, a.dc);
    t += fmt::format(
        "band_low_hz = {}\nband_high_hz = {}\nrolloff_db_per_octave = {}\n"
        "rise_ms = {}\n",
        a.band_low_hz, a.band_high_hz, a.rolloff_db_per_octave, a.rise_ms);
    t += fmt::format("\n[response]\nkind = \"{}\"\n",
                     kResonanceKinds[static_cast<int>(a.resonance)]);
    if (a.resonance != ResonanceKind::none)
        t += fmt::format("resonance_hz = {}\nq = {}\n", a.resonance_hz, a.q);
    if (!a.points.empty()) {
        t += "points = [\n";
        for (const auto& [f, db] : a.points) t += fmt::format("  [{}, {}],\n", f, db);
        t += "]\n";
    }
    if (a.type == ActuatorType::erm)
        t +=
            fmt::format("\n[erm]\nfrequency_at_min_drive_hz = {}\nfrequency_at_max_drive_hz = {}\n",
                        a.erm_min_drive_hz, a.erm_max_drive_hz);
    return t;
}

}  // namespace tactus
