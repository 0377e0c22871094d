// What an actuator does with its drive, in the time domain: drive (full scale) -> displacement,
// in units of the profile's displacement_um (1 = displacement_um um peak; for a linear actuator
// a full-scale sine at reference_hz gives 1). The measure of a render "through the actuator"
// (tactus simulate, tactus meter; eval/actuators.py). Values are the profile's, typical of the
// class, not measurements (profile.hpp).
//   voice coil, LRA (linear): the profile's response_db as a filter: its resonance as an exact
//       biquad (low-pass: a driven mass-spring's displacement; band-pass: an LRA's peak at f0 with
//       its Q, 0 dB there), the band's roll-offs as Butterworth edges at band_low_hz and
//       band_high_hz (order rolloff_db_per_octave / 6, in 2nd-order sections), and a FittedEq
//       for the rest (table points, the edges' corners, the reference's level) over an octave
//       beyond the band. The ring-up and ring-down (an LRA's ~Q / (pi f0)) follow from it.
//   ERM: a DC motor whose speed follows the drive (signed: a bipolar carrier averages out, it
//       only buzzes) through a one-pole lag of time constant rise_ms / ln 9 (rise_ms read as
//       the 10-90 % rise, docs/perception.md "Actuators": 50-100 ms); it vibrates at its speed:
//       frequency_at_min_drive_hz + (max - min) x |speed| [read: TDK table, frequency tied to
//       drive], amplitude |speed| [assumed: linear in speed, between a skin-stiffness load
//       (force ~ speed^2) and a free mass (constant)].
// prepare() allocates (a control thread); reset() and process() are real-time safe.
#pragma once

#include <array>

#include "tactus/actuator/profile.hpp"
#include "tactus/dsp/biquad.hpp"
#include "tactus/dsp/fitted_eq.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

// An ERM's spin-up time constant (ms) from its profile's 10-90 % rise_ms.
double erm_spin_time_constant_ms(const ActuatorProfile& actuator);

class ActuatorModel {
  public:
    static constexpr int kMaxEdgeSections = 4;  // per edge: up to 48 dB/octave

    void prepare(const ProcessSpec& spec, const ActuatorProfile& actuator);
    void reset() noexcept;
    // drive -> displacement, `count` samples; the buffers may alias.
    void process(const float* drive, float* displacement, int count) noexcept;
    int latency() const { return 0; }
    // A linear actuator's response (dB re reference_hz), as the filter achieves it.
    double magnitude_db(double frequency_hz) const;

  private:
    double fixed_db(double frequency_hz) const;  // resonance and edges
    ActuatorProfile actuator_;
    double sample_rate_hz_ = 48000;
    bool erm_ = false;
    Biquad resonance_;
    bool resonance_on_ = false;
    std::array<Biquad, size_t{2} * kMaxEdgeSections> edges_;
    int edge_count_ = 0;
    FittedEq rest_;
    // ERM
    double follow_ = 1.0, speed_ = 0.0, phase_ = 0.0;
};

}  // namespace tactus
