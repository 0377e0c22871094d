// What one actuator output plays. The paper drives every tonehole with one signal (§6); a device
// with several actuators says more when each says something of its own: the whole input (`all`,
// the paper's), only some drum parts' pulses (`kick`, `snare+hat`: the parts of
// analysis/drum_part.hpp; with a hit named another part, when its parts are at least
// parts.route_min likely), a band of the input analysed on its own, so its loudness, onsets and
// brightness are the band's (`band:LOW-HIGH`, Hz), or one input channel, so stereo or surround
// direction reaches left and right actuators (`channel:N`, counted from 1; a mono input is every
// channel, as a mono sound plays on both sides). On top of the running settings an output may
// also take its own values of the mapping's parameters (its overlay: a pitch range, an
// envelope, a part's gain), as a preset would set them, fitted to its actuator as the settings
// are (Engine::as_played).
// Any thread: parse(), text(), check_overlay(); the engine turns routes into its pipeline's
// lanes (engine/pipeline.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tactus/analysis/drum_part.hpp"
#include "tactus/params/params.hpp"

namespace tactus {

struct Route {
    enum class Kind : uint8_t { all, parts, band, channel };
    static constexpr double kMinBandHz = 10;
    static constexpr double kMaxBandHz = 8000;  // the analysis's spectrum ends here (16 kHz)
    static constexpr int kMaxChannel = 16;      // input channels a route may take (from 1)

    Kind kind = Kind::all;
    uint8_t parts = 0;               // parts: a bit per DrumPart
    double low_hz = 0, high_hz = 0;  // band
    int channel = 0;                 // channel: counted from 0

    // "all", "kick", "kick+snare", "band:20-120", "channel:1"; throws std::invalid_argument
    // naming the text and what is allowed.
    static Route parse(std::string_view text);
    std::string text() const;  // parse(text()) == *this
    // Its own analysis: a band's or a channel's, not the engine's mix.
    bool own_analysis() const { return kind == Kind::band || kind == Kind::channel; }
    bool plays(DrumPart part) const {
        return kind != Kind::parts || (parts >> static_cast<int>(part) & 1) != 0;
    }
    // How likely a hit is one of the parts it plays, given each drum part's probability.
    double share_of(const std::array<float, 3>& part_probability) const {
        double share = 0;
        for (size_t p = 0; p < part_probability.size(); ++p)
            if (plays(static_cast<DrumPart>(p))) share += part_probability[p];
        return share;
    }
    // The same input heard the same way (one analysis serves both).
    bool hears_as(const Route& other) const;
    bool operator==(const Route&) const = default;
};

// An output's own values of mapping parameters, applied over the running settings in order.
using Overlay = std::vector<std::pair<P, double>>;

// The parameters an overlay may set: the live ones the mapping reads (mapping.*, envelope.*,
// parts.<part>.*); throws std::invalid_argument naming the key and the value.
void check_overlay(const Overlay& overlay);
// `settings` with the overlay's values.
Settings overlaid(Settings settings, const Overlay& overlay) noexcept;

}  // namespace tactus
