// P-channel flattening filter (paper §6: "a frequency flattening function to compensate for the
// non-linear response of the upper ranges of vibrotaction (P channel)"), designed from the
// perception model: the P threshold curve for the contact area (perception/threshold.hpp), or
// the equal-sensation contour at a level above threshold, whose relief shrinks as level rises
// (perception/sensation.hpp).
// Target: gain(f) = -min(strength * (C_max - C(f)), range_db), C the contour, held flat below
// 40 Hz (there NPI sets the threshold, flat 20-40 Hz: paper §3.2) and C_max its largest value in
// the band: the filter only attenuates, the least sensitive frequency passes at unity; the
// level spread is bounded by range_db. Realised by FittedEq (peaking biquads fitted in dB).
#pragma once

#include "tactus/dsp/fitted_eq.hpp"
#include "tactus/dsp/process_spec.hpp"
#include "tactus/perception/threshold.hpp"

namespace tactus {

struct FlatteningDesign {
    double low_hz = 20;  // the band designed for (the post chain's)
    double high_hz = 1000;
    double strength = 1.0;   // fraction of the contour compensated
    double range_db = 30.0;  // largest attenuation
    double contact_area_cm2 = perception::kReferenceAreaCm2;
    double level_db = 0.0;  // SL of the equal-sensation contour (0: threshold)
    bool operator==(const FlatteningDesign&) const = default;
};

class FlatteningFilter {
  public:
    // A complete design, copied without allocation: what a control thread hands the audio thread.
    struct Design {
        FlatteningDesign inputs;
        double reference_db = 0;
        FittedEq::Design eq;
    };
    // Allocates (the fit). Control and setup threads: the design made at build time for the
    // rate and inputs (flattening_designs.hpp), or the one made before in the process
    // (dsp/design_memo.hpp), or one made now (flattening_designs.cpp).
    static Design design(double sample_rate_hz, const FlatteningDesign& inputs);
    // A design made now: the contour's reference scan (thousands of threshold evaluations) and
    // the fit. Allocates.
    static Design make_design(double sample_rate_hz, const FlatteningDesign& inputs);
    void prepare(const ProcessSpec& spec, const FlatteningDesign& inputs);  // may allocate
    void reset() noexcept { eq_.reset(); }
    int latency() const { return 0; }  // minimum phase
    // Audio thread: glides to a design() made for the same rate and band over `samples`.
    void glide_to(const Design& design, int samples) noexcept {
        design_ = design.inputs;
        reference_db_ = design.reference_db;
        eq_.glide_to(design.eq, samples);
    }
    void process(float* samples, int count) noexcept { eq_.process(samples, count); }

    double target_db(double frequency_hz) const;  // what the design aims for
    double magnitude_db(double frequency_hz) const { return eq_.magnitude_db(frequency_hz); }

  private:
    double contour_db(double frequency_hz) const;
    FlatteningDesign design_;
    double reference_db_ = 0;
    FittedEq eq_;
};

}  // namespace tactus
