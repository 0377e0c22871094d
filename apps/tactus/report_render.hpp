// The render behind `tactus report` and `tactus studio`: one pass of the engine over a file
// (export/haptic_track.hpp's render_haptic_tracks, as `tactus export` runs it) that gathers the
// report's plots (waveform with onsets, features, vibration program, vibration, felt envelope,
// sensation per channel of touch) and the sound and the vibration lined up in time. Any thread;
// one call per Engine.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis_cache.hpp"
#include "tactus/actuator/profile.hpp"
#include "tactus/export/html_report.hpp"
#include "tactus/io/layout_file.hpp"
#include "tactus/io/run_file.hpp"
#include "tactus/params/params.hpp"
#include "tactus/perception/meter.hpp"

namespace tactus::cli {

// One actuator output's drive, metered through its profile.
struct MeteredOutput {
    std::string name;          // the layout's name of it; "" for the one output of no layout
    std::string metered_name;  // the profile metered through (its own, else the default)
    perception::MeterSummary summary;
};

struct ReportRender {
    std::vector<ReportPlot> plots;    // at most about kMaxPlotRows rows each
    std::vector<ReportOnset> onsets;  // with their drum parts
    // The channels' mean and the first actuator's drive, lined up: vibration[k] is what
    // `tactus render` writes at latency_frames + k (the engine's latency taken off).
    std::vector<float> sound, vibration;
    double sample_rate_hz = 0;
    int64_t latency_frames = 0;
    std::vector<MeteredOutput> metered;  // every output, in order
    std::string unfelt_warning;          // render's warning of sound left unfelt, or ""
    bool analysis_replayed = false;      // the analysis kept in `analyses` played back
};

// Renders `input` with `settings` for `actuator` (none: no compensation, metered through the
// default actuator), or with `layout` (its outputs, each its route and profile: the felt plot
// has one series per output, named, the onsets are those the outputs play, each output has its
// drive and sensation plots, metered through its own profile; the players hold the first
// output's); throws std::runtime_error with a one-line message naming the file. With
// `analyses`, an analysis kept there for the file and the analysis's settings is played back
// (the same vibration, bit for bit, without analysing again), else the file is analysed and
// its analysis kept (a render ringing out past what was kept analyses again).
ReportRender render_report(const std::string& input, const Settings& settings,
                           const std::optional<ActuatorProfile>& actuator,
                           const RunCallbacks& callbacks = {}, AnalysisCache* analyses = nullptr,
                           const Layout* layout = nullptr);

}  // namespace tactus::cli
