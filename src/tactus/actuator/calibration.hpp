// Measuring an actuator (tactus calibrate): Farina's method. An exponential sine sweep drives
// the actuator, a sensor on it (accelerometer, contact microphone) is recorded, and deconvolving
// the recording by the sweep gives the impulse response, in which the harmonic distortion
// products arrive before the linear response and are windowed out (A. Farina, "Simultaneous
// measurement of impulse response and distortion with a swept-sine technique", AES 108th
// convention, 2000). The magnitude of the linear response, smoothed over 1/48 octave, becomes
// the points of an actuator profile (actuator/profile.hpp). Setup thread only (allocates).
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "tactus/actuator/profile.hpp"

namespace tactus {

struct SweepSpec {
    double sample_rate_hz = 48000;
    double low_hz = 20, high_hz = 2000;  // swept, exponentially
    double seconds = 5;
    double level = 0.5;                     // full scale
    static constexpr double kFadeS = 0.01;  // raised-cosine fades at both ends
};

// The sweep sin(2 pi f1 L (exp(t / L) - 1)), L = T / ln(f2 / f1). Throws std::invalid_argument
// for a band outside (0, rate / 2) or a level outside (0, 1].
std::vector<float> exponential_sweep(const SweepSpec& spec);

// The response in dB (relative, unnormalised) at `points_per_octave` log-spaced frequencies
// inside the sweep's band (a third of an octave in from its ends, where the fades are),
// measured from `recorded`: the sensor's signal while the sweep played, starting at or before the
// sweep's start and holding its whole response (the device delay is found). Throws
// std::runtime_error when the recording holds no response.
std::vector<std::pair<double, double>> measure_response(std::span<const float> sweep,
                                                        std::span<const float> recorded,
                                                        const SweepSpec& spec,
                                                        int points_per_octave = 48);

// A profile whose response is `measured` (points relative to 0 dB at reference_hz, no
// resonance model, no extra roll-off: the points are the response): the other fields from
// `base` (type, displacement, drive, dc, rise, reference and band). Without a base: a voice-coil
// referenced at the response's peak, its band where the response is within kBandDb of the peak.
inline constexpr double kBandDb = 12;
ActuatorProfile measured_profile(const std::vector<std::pair<double, double>>& measured,
                                 const ActuatorProfile* base);

}  // namespace tactus
