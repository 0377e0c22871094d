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
//                  with their parts and strengths beside them. Steps last kAndroidMinStepMs at
//                  least, and an amplitude below the actuator's felt floor (felt_floor.hpp) is 0:
//                  a phone without amplitude control plays every other amplitude at full
//                  strength, so a tail too weak to feel would buzz.
//   .envelope.json Android envelope effects, VibrationEffect.BasicEnvelopeBuilder (API 36):
//                  an initial sharpness, then control points (intensity 0-1, sharpness 0-1, the
//                  milliseconds to reach them, at least kAndroidMinStepMs each) drawn from the
//                  felt envelope's breakpoints, the last at zero intensity as the builder
//                  requires; the onsets beside them.
// Values are rounded to what a device resolves (0.1 ms, 1e-3 of full scale). Intensity 1 (255) is
// the track's full scale (normalisation.hpp), stated in each format's description.
#pragma once

#include <string>

#include "tactus/export/haptic_track.hpp"

namespace tactus {

inline constexpr double kAhapMaxEventS = 30.0;       // a continuous event's longest duration
inline constexpr int kAhapMaxCurvePoints = 16;       // control points per ParameterCurve
inline constexpr int kAndroidWaveformApiLevel = 26;  // VibrationEffect.createWaveform
inline constexpr int kAndroidEnvelopeApiLevel = 36;  // VibrationEffect.BasicEnvelopeBuilder
inline constexpr int kAndroidMaxAmplitude = 255;

// Breakpoint tolerances (of full scale): the envelope is drawn within these of the felt one.
inline constexpr double kIntensityTolerance = 0.01;
inline constexpr double kSharpnessTolerance = 0.02;
// An Android step holds one amplitude while the envelope stays within this range.
inline constexpr double kAndroidStepRange = 0.02;
// The shortest Android step. Android drives the vibrator through the framework, one
// setAmplitude call per step (binder to the vibrator HAL), on actuators that resolve no shorter:
// a phone's LRA rises in 10-20 ms (docs/perception.md; lra-175's rise_ms is 15), Android's own
// guidance has a crisp click last 10-20 ms ("Analyze vibration waveforms", developer.android.com),
// and pulses under ~20 ms are hard to feel on phone actuators (perception.md). A shorter step is
// never reached, only adds a call: 20 ms, the top of that range.
inline constexpr int kAndroidMinStepMs = 20;
// The actuator an Android waveform plays on when none is named: a phone's LRA.
inline constexpr const char* kAndroidActuator = "lra-175";

std::string ahap_text(const HapticTrack& track);
std::string meta_haptic_text(const HapticTrack& track);
// floor: the weakest drive felt (0 ... 1, felt_floor.hpp); amplitudes below it are written 0.
std::string android_waveform_text(const HapticTrack& track, double floor);
std::string android_envelope_text(const HapticTrack& track);
// The lowest amplitude (1-255) at or above `floor`.
int android_lowest_amplitude(double floor);

// The format named by a path's ending (".ahap", ".haptic", ".android.json", ".envelope.json",
// ".ogg"), or empty.
std::string haptic_format_of(const std::string& path);

}  // namespace tactus
