// Vibrotactile detection thresholds of the four channels (channels.hpp) vs frequency, in dB re
// 1 um peak displacement, after docs/perception.md. Reference condition: thenar eminence, 2.9 cm^2
// contactor with a rigid surround, 1 s bursts (Bolanowski, Gescheider, Verrillo & Checkosky
// 1988, JASA 84:1680).
//   P:     T_P(f) = T_Pmin + 10 log10( (3/7)(f_m/f)^4 + (4/7)(f/f_m)^3 ), f_m = 250 Hz: falls
//          12 dB/octave to the minimum (Verrillo 1963), rises ~9 dB/octave above (Verrillo 1966).
//   NPI:   flat from ~3 to 40 Hz with a shallow notch (lower threshold) at 30 Hz (Table 1).
//   NPII:  the P U-shape, 20-25 dB higher.
//   NPIII: flat from DC to ~3 Hz.
// Only P sums over area and duration (Verrillo 1963, 1965; Gescheider 1976): -3 dB per doubling
// of contactor area between 0.02 and 2.9 cm^2 and -3 dB per doubling of duration up to 1 s, full
// at >= 80 Hz and none at <= 40 Hz. The whole system detects at the lowest channel threshold
// (min rule: Gescheider et al. 2004, Behav Brain Res 148:35).
// [recalled] levels are named constants below; the curve shapes are what tests hold tightly.
#pragma once

#include <cmath>

#include "tactus/perception/channels.hpp"

namespace tactus::perception {

// P channel, reference condition.
constexpr double kPBestHz = 250.0;                             // f_m [derived, docs/perception.md]
constexpr double kPMinimumDb = -20.0;                          // T_Pmin [recalled, +-5 dB]
constexpr double kPLowEdgeHz = info(Channel::P).range_low_hz;  // 40-500 Hz (paper Table 1)
constexpr double kPHighEdgeHz = info(Channel::P).range_high_hz;

// NPI: flat +10 to +15 dB from ~3 to 40 Hz [recalled]; the notch at 30 Hz (Table 1, note 3) is
// modelled shallow: depth and width are assumptions, not data. Below 3 Hz it rises steeply
// enough for NPIII to set the threshold under ~1.8 Hz, inside the overlap of the two channels'
// Table 1 ranges (NPI 2-40 Hz, NPIII 0.4-3 Hz) [derived].
constexpr double kNpiFlatDb = 12.5;                                    // [recalled, +10 to +15 dB]
constexpr double kNpiLowCornerHz = 3.0;                                // [recalled]
constexpr double kNpiHighCornerHz = info(Channel::NPI).range_high_hz;  // 40 Hz (Table 1)
constexpr double kNpiLowSlopeDbPerOctave = 24;  // [derived] below the flat range
constexpr double kNpiHighSlopeDbPerOctave = 6;  // [assumed] above the flat range
constexpr double kNpiNotchHz = 30.0;            // Table 1, note 3
constexpr double kNpiNotchDepthDb = 3.0;        // [assumed: "shallow"]
constexpr double kNpiNotchWidthOctaves = 0.5;   // [assumed] standard deviation in octaves

// NPII: the P shape raised by 20-25 dB [recalled]; no spatial summation (Gescheider et al. 2001).
constexpr double kNpiiAbovePDb = 22.5;

// NPIII: flat +25 to +35 dB from 0.4 to ~3 Hz [recalled], flat down to a static indentation.
constexpr double kNpiiiFlatDb = 30.0;  // [recalled, +25 to +35 dB]
constexpr double kNpiiiHighCornerHz = info(Channel::NPIII).range_high_hz;  // 3 Hz (Table 1)
constexpr double kNpiiiHighSlopeDbPerOctave = 9.0;  // [assumed] above the flat range

// Summation (P only).
constexpr double kReferenceAreaCm2 = 2.9;         // contactor of the reference curves
constexpr double kSmallestSummingAreaCm2 = 0.02;  // no spatial summation below [read]
constexpr double kReferenceDurationS = 1.0;       // temporal summation up to ~1 s [recalled]
constexpr double kShortestDurationS = 0.01;       // shortest burst the law is applied to [assumed]
constexpr double kSummationDbPerDoubling = 3.0;   // area and duration [read; recalled]
constexpr double kNoSummationBelowHz = 40.0;      // none at 25-40 Hz [read]
constexpr double kFullSummationAboveHz = 80.0;    // full at 80-320 Hz [read]

// The stimulus conditions a threshold depends on.
struct Stimulus {
    double contact_area_cm2 = kReferenceAreaCm2;
    double duration_s = kReferenceDurationS;
};

// T_P(f) at the reference condition (2.9 cm^2, 1 s).
inline double p_threshold_db(double frequency_hz) {
    const double r = kPBestHz / frequency_hz;
    return kPMinimumDb + 10.0 * std::log10((3.0 / 7.0) * r * r * r * r + (4.0 / 7.0) / (r * r * r));
}

// Threshold of one channel, dB re 1 um peak.
double threshold_db(Channel channel, double frequency_hz, const Stimulus& stimulus = {});
// Whole-system threshold: the lowest channel threshold (min rule), and the channel setting it.
double detection_threshold_db(double frequency_hz, const Stimulus& stimulus = {});
Channel detecting_channel(double frequency_hz, const Stimulus& stimulus = {});

}  // namespace tactus::perception
