// The mapping stage: analysis features -> vibration program (paper §6 and Figure 4).
// Amplitude, frequency and square mix each come from a FeatureMapping; onsets become envelope
// triggers. Below the loudness gate the amplitude is 0 and frequency and mix hold their values,
// so silence (and the noise floor) never sets the carrier.
#pragma once

#include "tactus/analysis/features.hpp"
#include "tactus/mapping/control_frame.hpp"
#include "tactus/mapping/feature_mapping.hpp"

namespace tactus {

class Mapper {
  public:
    void prepare(const Settings& settings, double frames_per_second);
    void reset() noexcept;
    ControlFrame map(const Features& features) noexcept;

  private:
    FeatureMapping amplitude_, frequency_, square_mix_;
    double gate_db_ = -70;
    ControlFrame envelope_;  // attack, decay, sustain from settings
};

}  // namespace tactus
