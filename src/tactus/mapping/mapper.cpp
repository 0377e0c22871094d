#include "tactus/mapping/mapper.hpp"

namespace tactus {

void Mapper::prepare(const Settings& s, double frames_per_second) {
    amplitude_.prepare(s, P::amplitude_source, frames_per_second);
    frequency_.prepare(s, P::frequency_source, frames_per_second);
    square_mix_.prepare(s, P::square_mix_source, frames_per_second);
    gate_db_ = s[P::mapping_gate_db];
    envelope_.attack_ms = s[P::envelope_attack_ms];
    envelope_.decay_ms = s[P::envelope_decay_ms];
    envelope_.sustain = s[P::envelope_sustain];
    reset();
}

void Mapper::reset() noexcept {
    amplitude_.reset(0.0);
    frequency_.reset(frequency_.shape(0.0));
    square_mix_.reset(square_mix_.shape(0.0));
}

ControlFrame Mapper::map(const Features& f) noexcept {
    ControlFrame frame = envelope_;
    frame.sample = f.frame_end_sample;
    if (f.loudness_db >= gate_db_) {
        frame.amplitude = amplitude_.map(f);
        frame.frequency_hz = frequency_.map(f);
        frame.square_mix = square_mix_.map(f);
        frame.trigger = f.onset;
    } else {
        amplitude_.reset(0.0);
        frame.amplitude = 0.0;
        frame.frequency_hz = frequency_.current();
        frame.square_mix = square_mix_.current();
    }
    return frame;
}

}  // namespace tactus
