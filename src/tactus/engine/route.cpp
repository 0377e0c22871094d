#include "tactus/engine/route.hpp"

#include <fmt/format.h>

#include <charconv>
#include <stdexcept>

#include "tactus/core/printable.hpp"

namespace tactus {
namespace {

constexpr std::string_view kAllowed =
    "all, a drum part or parts joined by + (kick, snare, hat, other), band:LOW-HIGH (Hz, 10-8000) "
    "or channel:N (1-16)";

[[noreturn]] void refuse(std::string_view text, std::string_view problem = {}) {
    throw std::invalid_argument(fmt::format("route '{}'{}{}: allowed {}", printable(text),
                                            problem.empty() ? "" : ": ", problem, kAllowed));
}

// A whole number or decimal, the whole of `text`.
bool read_number(std::string_view text, double& value) {
    const char* end = text.data() + text.size();
    const auto [at, error] = std::from_chars(text.data(), end, value);
    return error == std::errc{} && at == end;
}

}  // namespace

Route Route::parse(std::string_view text) {
    Route route;
    if (text == "all") return route;
    if (text.starts_with("band:")) {
        const std::string_view range = text.substr(5);
        const size_t dash = range.find('-');
        route.kind = Kind::band;
        if (dash == std::string_view::npos || !read_number(range.substr(0, dash), route.low_hz) ||
            !read_number(range.substr(dash + 1), route.high_hz))
            refuse(text, "a band is two numbers in Hz, LOW-HIGH");
        if (!(route.low_hz >= kMinBandHz && route.low_hz < route.high_hz &&
              route.high_hz <= kMaxBandHz))
            refuse(text, "the band must lie in 10-8000 Hz, its low edge below its high one");
        return route;
    }
    if (text.starts_with("channel:")) {
        const std::string_view number = text.substr(8);
        int channel = 0;
        const auto [at, error] =
            std::from_chars(number.data(), number.data() + number.size(), channel);
        if (error != std::errc{} || at != number.data() + number.size() || channel < 1 ||
            channel > kMaxChannel)
            refuse(text, "the channel is a whole number from 1 to 16");
        route.kind = Kind::channel;
        route.channel = channel - 1;
        return route;
    }
    route.kind = Kind::parts;
    for (size_t start = 0; start <= text.size();) {
        const size_t plus = std::min(text.find('+', start), text.size());
        const std::string_view name = text.substr(start, plus - start);
        int part = 0;
        while (part < kDrumParts && kDrumPartNames[static_cast<size_t>(part)] != name) ++part;
        if (part == kDrumParts) refuse(text);
        route.parts |= static_cast<uint8_t>(1 << part);
        start = plus + 1;
    }
    return route;
}

std::string Route::text() const {
    switch (kind) {
        case Kind::all:
            return "all";
        case Kind::band:
            return fmt::format("band:{:g}-{:g}", low_hz, high_hz);
        case Kind::channel:
            return fmt::format("channel:{}", channel + 1);
        case Kind::parts:
            break;
    }
    std::string names;
    for (int part = 0; part < kDrumParts; ++part)
        if (plays(static_cast<DrumPart>(part))) {
            if (!names.empty()) names += '+';
            names += kDrumPartNames[static_cast<size_t>(part)];
        }
    return names;
}

bool Route::hears_as(const Route& other) const {
    if (own_analysis() || other.own_analysis()) return *this == other;
    return true;  // all and parts: the engine's mix
}

void check_overlay(const Overlay& overlay) {
    Settings settings;
    for (const auto& [id, value] : overlay) {
        const ParamSpec& s = spec(id);
        const bool mapping = s.key.starts_with("mapping.") || s.key.starts_with("envelope.") ||
                             (s.key.starts_with("parts.") && s.key.find('.', 6) != s.key.npos);
        if (!mapping || s.change != ParamChange::live)
            throw std::invalid_argument(
                fmt::format("{}: an output may set only the mapping's live parameters "
                            "(mapping.*, envelope.*, parts.<part>.*)",
                            s.key));
        settings.set(id, value);  // throws naming the key and its range
    }
}

Settings overlaid(Settings settings, const Overlay& overlay) noexcept {
    for (const auto& [id, value] : overlay) settings.assign(id, value);
    return settings;
}

}  // namespace tactus
