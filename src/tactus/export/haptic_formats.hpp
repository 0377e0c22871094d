// Writers of the haptic file formats the platforms play, each from a HapticTrack, each after
// its published specification:
//   .ahap          Apple Core Haptics, "Representing haptic patterns in AHAP files": Version,
//                  Metadata (with each onset's part and strength: Onsets, a list; Core Haptics
//                  ignores keys it does not know), Pattern of HapticTransient events at the
//                  onsets and HapticContinuous
//                  events (at most kAhapMaxEventS each) whose HapticIntensityControl and
//                  HapticSharpnessControl ParameterCurves (at most kAhapMaxCurvePoints points
//                  each: longer curves fail on devices) follow the felt envelope.
//   .haptic        Meta Haptics SDK / Lofelt data model v1 (haptic-file-spec.md): version,
//                  metadata, signals.continuous.envelopes: amplitude breakpoints (emphasis at
//                  the onsets, never below the breakpoint's amplitude) and frequency (0-1), times
//                  non-decreasing, at least two breakpoints, the frequency envelope ending with
//                  the amplitude's.
//   .android.json  Android VibrationEffect.createWaveform(long[] timings, int[] amplitudes,
//                  int repeat) (API 26): steps in ms, amplitudes 0 (off) or 1-255; the onsets
//                  with their parts and strengths beside them.
// Values are rounded to what a device resolves (0.1 ms, 1e-3 of full scale).
#pragma once

#include <string>

#include "tactus/export/haptic_track.hpp"

namespace tactus {

inline constexpr double kAhapMaxEventS = 30.0;       // a continuous event's longest duration
inline constexpr int kAhapMaxCurvePoints = 16;       // control points per ParameterCurve
inline constexpr int kAndroidWaveformApiLevel = 26;  // VibrationEffect.createWaveform
inline constexpr int kAndroidMaxAmplitude = 255;

// Breakpoint tolerances (of full scale): the envelope is drawn within these of the felt one.
inline constexpr double kIntensityTolerance = 0.01;
inline constexpr double kSharpnessTolerance = 0.02;
// An Android step holds one amplitude while the envelope stays within this range.
inline constexpr double kAndroidStepRange = 0.02;

std::string ahap_text(const HapticTrack& track);
std::string meta_haptic_text(const HapticTrack& track);
std::string android_waveform_text(const HapticTrack& track);

// The format named by a path's ending (".ahap", ".haptic", ".android.json", ".ogg"), or empty.
std::string haptic_format_of(const std::string& path);

}  // namespace tactus
