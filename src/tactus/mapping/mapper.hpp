// The mapping stage: analysis features -> vibration program (paper §6 and Figure 4).
// Amplitude, frequency and square mix each come from a FeatureMapping; onsets become envelope
// triggers. Below the loudness gate the amplitude is 0 and frequency and mix hold their values,
// so silence (and the noise floor) never sets the carrier.
// The further channels (paper §5: features mapped onto weighted combinations of channels) come
// from their own FeatureMappings: NPI flutter level and rate, NPIII pressure level, each times
// its weight. Flutter equalisation (§5.2): "if all vibration channels are to be engaged equally
// loudly, average vibration intensity should be de-emphasized" in NPI's range, if innervation
// sets perceived magnitude; we take magnitude proportional to the number of fibres excited, so
// the flutter amplitude is scaled by the innervation ratio P / NPI = 21 / 140 (-16.5 dB, Table
// 1). Pressure steps (§5.4: "multiple levels of sustained pressure") quantise the level to
// `pressure.steps` levels above 0 with a hysteresis of 0.1 step, so a level near a boundary
// does not chatter. Without actuator.dc the pressure is exactly 0.
// One frequency per pulse (mapping.frequency.hold; §6: onsets make "discrete vibrotactile
// pulses" at the brightness's pitch): an onset's frame maps the frequency without smoothing, so
// a pulse after silence starts at its own pitch rather than gliding up from the floor; the pulse
// follows the mapping, unsmoothed, for mapping.frequency.settle_ms (a hit's first frames mix it
// with what came before and its click), then keeps that frequency until the next onset, however
// the brightness of its decay wanders. Off, the frequency is smoothed throughout.
// By drum part (parts.*): once a pulse's part is decided (parts.settle_ms after its onset;
// analysis/hit_analysis.hpp) the pulse takes its part's gain, its part's brightness through the
// frequency mapping (so an actuator's fit of that mapping fits it too) and its part's decay, each
// where set: a kick low and long, a snare high, hats short and light, the rest of a mix off
// ("drums only"). Before the decision, and with nothing set, the pulse is the mapping's.
#pragma once

#include <array>

#include "tactus/analysis/features.hpp"
#include "tactus/core/units.hpp"
#include "tactus/mapping/control_frame.hpp"
#include "tactus/mapping/feature_mapping.hpp"

namespace tactus {

// What a mapper is prepared for, by name.
struct MappingSpec {
    double frames_per_second = 100;  // analysis frames: the mapping runs once per frame
    // Full scale: the post chain's ceiling (PostChain::ceiling(), lowered by an actuator's max
    // drive), which the pressure weight is a fraction of.
    double output_ceiling = 1;
};

class Mapper {
  public:
    void prepare(const Settings& settings, const MappingSpec& spec);
    // Without an actuator: the ceiling is post.ceiling_db.
    void prepare(const Settings& settings, double frames_per_second) {
        prepare(settings, {.frames_per_second = frames_per_second,
                           .output_ceiling = db_to_gain(settings[P::post_ceiling_db])});
    }
    void reset() noexcept;
    // Live (audio thread): every mapping setting; smoothed values and pressure steps go on.
    void set_live(const Settings& settings, double output_ceiling) noexcept;
    ControlFrame map(const Features& features) noexcept;

  private:
    // What a part sets of its pulses (parts.<part>.*): 0 where it leaves the mapping's.
    struct PartShape {
        double gain = 1, brightness_hz = 0, decay_ms = 0;
    };
    void apply_part(const Features& features, ControlFrame& frame) noexcept;
    double pressure_of(const Features& features) noexcept;
    double frequency_of(const Features& features) noexcept;

    FeatureMapping amplitude_, frequency_, square_mix_;
    FeatureMapping flutter_level_, flutter_rate_, pressure_level_;
    double flutter_gain_ = 0, pressure_weight_ = 0;
    int pressure_steps_ = 0, pressure_step_ = 0;
    bool hold_frequency_ = false;
    double settle_frames_ = 0;  // frames after an onset's frame the frequency still follows
    int pulse_frames_ = -1;     // frames since the last onset's frame; -1: no pulse yet
    double gate_db_ = -70, frames_per_second_ = 1;
    ControlFrame envelope_;  // attack, decay, sustain from settings
    std::array<PartShape, kDrumParts> parts_{};
    bool part_known_ = false;  // the sounding pulse's part is decided: pulse_part_
    DrumPart pulse_part_ = DrumPart::other;
};

}  // namespace tactus
