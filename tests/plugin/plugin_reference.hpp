// The engine library driven as a host drives the plugin (the same blocks, Engine::set between
// them), for the plugin tests to compare against; a host change is a parameter's stable id and
// value, as CLAP and this project's LV2 host send it.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "plugin_audio.hpp"
#include "tactus/engine/engine.hpp"

namespace tactus::test {

constexpr uint32_t kBlock = 256;  // not render's 4096: any block split renders the same
constexpr int kActuators = 2;     // the plugin's vibration outputs

using Outputs = std::vector<std::vector<float>>;  // vibration 1..N, music L, R (delayed)

struct ParamChange {
    uint32_t id;  // stable id (= CLAP param id)
    double value;
    uint32_t frame = 0;
};

struct Automation {
    size_t block;  // sent between block-1 and block
    std::vector<ParamChange> changes;
};

// The engine library driven as the plugin drives it: the same blocks, set() between them.
inline Outputs engine_reference(const Sound& sound, const std::vector<Automation>& automation) {
    Engine engine;
    engine.set_actuators(std::vector<ActuatorOutput>(kActuators));
    engine.prepare({.sample_rate_hz = sound.sample_rate_hz, .max_block = kBlock, .channels = 2});
    Outputs out(kActuators, std::vector<float>(sound.frames()));
    for (size_t start = 0, block = 0; start < sound.frames(); start += kBlock, ++block) {
        for (const Automation& a : automation)
            if (a.block == block)
                for (const ParamChange& c : a.changes) engine.set(*find_param(c.id), c.value);
        const int n = static_cast<int>(std::min<size_t>(kBlock, sound.frames() - start));
        const float* in[2] = {sound.channels[0].data() + start, sound.channels[1].data() + start};
        float* o[kActuators] = {out[0].data() + start, out[1].data() + start};
        engine.process(in, o, n);
    }
    return out;
}

// A layout of the plugin's two outputs using every part of one: the low band through an LRA's
// profile; the snare, trimmed, with its own pitch ceiling; the second one `delay_ms` late.
inline std::string two_part_layout(double delay_ms = 0) {
    return "[[output]]\nname = \"low\"\nroute = \"band:20-200\"\nactuator = \"lra-175\"\n"
           "[[output]]\nname = \"snare\"\nroute = \"snare\"\ngain_db = -6\ndelay_ms = " +
           std::to_string(delay_ms) + "\n[output.set]\nmapping.frequency.out_max = 200\n";
}

// The block just before the loudest vibration in [from_s, to_s): a change there lands on a hit.
inline size_t block_before_peak(const std::vector<float>& x, double rate_hz, double from_s,
                                double to_s) {
    size_t peak = static_cast<size_t>(from_s * rate_hz);
    for (size_t i = peak; i < static_cast<size_t>(to_s * rate_hz); ++i)
        if (std::abs(x[i]) > std::abs(x[peak])) peak = i;
    return peak / kBlock - 2;
}

}  // namespace tactus::test
