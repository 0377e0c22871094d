#include "tactus/mapping/mapper.hpp"

#include <algorithm>
#include <cmath>

#include "tactus/core/units.hpp"
#include "tactus/params/components.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {
// The first of a part's parameters (gain_db, brightness_hz, decay_ms follow it in the table).
constexpr P next(P first, int by) {
    return static_cast<P>(static_cast<int>(first) + by);
}
constexpr P part_first(DrumPart part) {
    return next(P::parts_kick_gain_db, 3 * static_cast<int>(part));
}
static_assert(part_first(DrumPart::other) == P::parts_other_gain_db &&
                  next(part_first(DrumPart::hat), 2) == P::parts_hat_decay_ms,
              "each part's three parameters, in DrumPart's order");
using perception::Channel;
// Innervation density P / NPI, human fingerpad (paper Table 1).
constexpr double kFlutterEqualizeGain = perception::info(Channel::P).innervation_per_cm2 /
                                        perception::info(Channel::NPI).innervation_per_cm2;
constexpr double kStepHysteresis = 0.1;   // of one step
constexpr int kMaxPulseFrames = 1 << 30;  // a pulse's frame count stops here (no overflow)
}  // namespace

void Mapper::prepare(const Settings& s, const MappingSpec& spec) {
    frames_per_second_ = spec.frames_per_second;
    set_live(s, spec.output_ceiling);
    reset();
}

void Mapper::set_live(const Settings& s, double output_ceiling) noexcept {
    const double fps = frames_per_second_;
    amplitude_.configure(s, P::amplitude_source, fps);
    frequency_.configure(s, P::frequency_source, fps);
    square_mix_.configure(s, P::square_mix_source, fps);
    flutter_level_.configure(s, P::flutter_level_source, fps);
    flutter_rate_.configure(s, P::flutter_rate_source, fps);
    pressure_level_.configure(s, P::pressure_level_source, fps);
    gate_db_ = s[P::mapping_gate_db];
    envelope_.attack_ms = s[P::envelope_attack_ms];
    envelope_.decay_ms = s[P::envelope_decay_ms];
    envelope_.sustain = s[P::envelope_sustain];
    // flutter.equalize glides from off (0) to on (1) when turned live: the gain in between.
    flutter_gain_ = flutter_enabled(s) ? s[P::flutter_weight] * std::lerp(1.0, kFlutterEqualizeGain,
                                                                          s[P::flutter_equalize])
                                       : 0.0;
    // Pressure weight is a fraction of the output ceiling (the post chain keeps that headroom).
    pressure_weight_ = pressure_enabled(s) ? s[P::pressure_weight] * output_ceiling : 0.0;
    pressure_steps_ = static_cast<int>(std::lround(s[P::pressure_steps]));
    pressure_step_ = std::min(pressure_step_, pressure_steps_);
    hold_frequency_ = s[P::frequency_hold] != 0.0;
    for (int part = 0; part < kDrumParts; ++part) {
        const P first = part_first(static_cast<DrumPart>(part));
        const double gain_db = s[first];
        parts_[part] = {.gain = gain_db <= spec(first).min ? 0.0 : db_to_gain(gain_db),
                        .brightness_hz = s[next(first, 1)],
                        .decay_ms = s[next(first, 2)]};
    }
    settle_frames_ = s[P::frequency_settle_ms] * 1e-3 * fps;
}

void Mapper::reset() noexcept {
    amplitude_.reset(0.0);
    frequency_.reset(frequency_.shape(0.0));
    square_mix_.reset(square_mix_.shape(0.0));
    flutter_level_.reset(0.0);
    flutter_rate_.reset(flutter_rate_.shape(0.0));
    pressure_level_.reset(0.0);
    pressure_step_ = 0;
    pulse_frames_ = -1;
    part_known_ = false;
}

double Mapper::pressure_of(const Features& f) noexcept {
    const double level = pressure_level_.map(f);
    if (pressure_steps_ <= 0) return pressure_weight_ * level;
    const double x = level * pressure_steps_;
    if (std::abs(x - pressure_step_) > 0.5 + kStepHysteresis)
        pressure_step_ = static_cast<int>(std::lround(x));
    return pressure_weight_ * pressure_step_ / pressure_steps_;
}

// With hold on: the onset's frame and the settle time after it map the frequency unsmoothed,
// then the pulse keeps it (mapper.hpp). Frames are counted from the onset's, so the settle time
// is the same at any hop.
double Mapper::frequency_of(const Features& f) noexcept {
    if (!hold_frequency_) return frequency_.map(f);
    if (f.onset) {
        pulse_frames_ = 0;
        return frequency_.jump(f);
    }
    if (pulse_frames_ < 0) return frequency_.map(f);
    if (pulse_frames_ < kMaxPulseFrames) ++pulse_frames_;
    if (pulse_frames_ > settle_frames_) return frequency_.current();
    return frequency_.jump(f);
}

// A pulse's part is unknown from its onset until its decision; from then on its part shapes it.
void Mapper::apply_part(const Features& f, ControlFrame& frame) noexcept {
    if (f.onset) part_known_ = false;
    if (f.part_decided) part_known_ = true, pulse_part_ = f.part;
    if (!part_known_) return;
    const PartShape& shape = parts_[static_cast<size_t>(pulse_part_)];
    frame.amplitude *= shape.gain;
    if (shape.brightness_hz > 0) frame.frequency_hz = frequency_.shape(shape.brightness_hz);
    if (shape.decay_ms > 0) frame.decay_ms = shape.decay_ms;
}

ControlFrame Mapper::map(const Features& f) noexcept {
    ControlFrame frame = envelope_;
    frame.sample = f.frame_end_sample;
    if (f.loudness_db >= gate_db_) {
        frame.amplitude = amplitude_.map(f);
        frame.frequency_hz = frequency_of(f);
        frame.square_mix = square_mix_.map(f);
        frame.trigger = f.onset;
        frame.flutter_amplitude = flutter_gain_ * flutter_level_.map(f);
        frame.flutter_hz = flutter_rate_.map(f);
        frame.pressure = pressure_of(f);
    } else {
        amplitude_.reset(0.0);
        flutter_level_.reset(0.0);
        pressure_level_.reset(0.0);
        pressure_step_ = 0;
        frame.amplitude = 0.0;
        frame.frequency_hz = frequency_.current();
        frame.square_mix = square_mix_.current();
        frame.flutter_hz = flutter_rate_.current();
    }
    apply_part(f, frame);
    return frame;
}

}  // namespace tactus
