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
    // Further channels of touch (paper §5.2, §5.4), each 0 when its component is off.
    double flutter_hz = 0;         // NPI flutter rate, 2 ... 40 Hz
    double flutter_amplitude = 0;  // full scale, weight and innervation equalisation applied
    double pressure = 0;           // NPIII offset, full scale, >= 0 (0 without actuator.dc)
};

}  // namespace tactus
