// One frame of the paper's "vibration program" (§5): what the synthesiser is told to do from
// `sample` on. The stream of these frames is the intermediate form between analysis and sound.
#pragma once

#include <cstdint>

namespace tactus {

struct ControlFrame {
    int64_t sample = 0;       // takes effect from this input sample
    double frequency_hz = 0;  // carrier frequency
    double amplitude = 0;     // 0 ... 1 full scale
    double square_mix = 0;    // 0 sine ... 1 square
    bool trigger = false;     // (re)start the envelope
    double attack_ms = 1;
    double decay_ms = 150;  // peak to -60 dB
    double sustain = 0;     // level the envelope decays to, 0 ... 1
};

}  // namespace tactus
