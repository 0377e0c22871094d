// A rendered vibration as the haptic formats describe one: a felt intensity and a sharpness
// envelope on a 1 ms grid, and the onsets (transients), all in the input's time (the engine's
// latency taken out, so the vibration lines up with the sound). Drawn from the vibration
// program (the onsets, each with its drum part, and the carrier of the engine's ControlFrames)
// and the rendered vibration (its felt envelope): docs/architecture.md, "The vibration program
// is the seam".
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tactus/engine/engine.hpp"
#include "tactus/engine/onset_decisions.hpp"
#include "tactus/io/render_info.hpp"
#include "tactus/io/run_file.hpp"

namespace tactus {

struct HapticOnset {
    double time_s = 0;
    double intensity = 0;  // 0 ... 1: the felt peak of its pulse, on the envelope's scale
    double sharpness = 0;  // 0 ... 1: its carrier frequency (sharpness_of) when its part was
                           // decided (the carrier may still glide on the onset's own frame)
    DrumPart part = DrumPart::other;  // its drum part and strength (engine/onset_decisions.hpp)
    double strength_db = -120;
};

struct HapticTrack {
    static constexpr double kStepS = 0.001;
    std::vector<double> intensity;  // 0 ... 1, felt amplitude (1: its peak, or normalise()'s)
    std::vector<double> sharpness;  // 0 ... 1, carrier frequency (sharpness_of)
    std::vector<HapticOnset> onsets;
    double felt_full_scale = 0;  // the felt amplitude intensity 1 stands for (1: full scale at
                                 // 250 Hz); as rendered, the envelope's peak
    std::string normalisation = "the peak is full scale";  // how, in words (normalisation.hpp)
    RenderInfo info;
    double duration_s() const { return static_cast<double>(intensity.size()) * kStepS; }
    // How it was made and normalised, one line: a format's description.
    std::string description() const { return info.describe() + "; " + normalisation; }
    // Intensity at any time, linear between steps.
    double intensity_at(double time_s) const;
};

// Carrier frequency -> 0 ... 1 on a log scale over the P channel's range (40-500 Hz, paper
// Table 1): Core Haptics' sharpness, the Meta format's normalised frequency.
double sharpness_of(double frequency_hz);

// Sound and vibration, lined up, as the export hands them on: audio[c][0 ... frames) for the
// input's channels (silence in the tail), vibration[a][...] for each actuator.
using AlignedSink = std::function<void(const float* const* audio, int audio_channels,
                                       const float* const* vibration, int actuators, int frames)>;

// Every analysis frame (features and vibration program), as the engine's frame queue gives it.
using FrameSink = std::function<void(const AnalysisFrame& frame)>;

// Runs `engine` (actuators set) over `input` and its tail and returns one track per actuator
// output (each its own felt envelope and full scale; its onsets those of the mix its route plays,
// or for a band or channel route its lane's own pulses); `sink`, if given, receives the sound and
// the vibration lined up, block by block, `frames` every analysis frame, and callbacks.on_output
// each block as the engine gives it (the latency included), after that block's frames.
// `analysis`: as run_file's.
std::vector<HapticTrack> render_haptic_tracks(const std::filesystem::path& input, Engine& engine,
                                              const AlignedSink& sink = {},
                                              const RunCallbacks& callbacks = {},
                                              const FrameSink& frames = {},
                                              RunAnalysis analysis = RunAnalysis::engine);

// A piecewise-linear approximation of values[i] at time i * step_s (Ramer-Douglas-Peucker):
// the fewest breakpoints that stay within `tolerance` of every value; first and last kept.
struct Breakpoint {
    double time_s = 0, value = 0;
};
std::vector<Breakpoint> simplify(const std::vector<double>& values, double step_s,
                                 double tolerance);

}  // namespace tactus
