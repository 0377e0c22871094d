// A self-contained HTML report (one file, no network: opened by double click): plots aligned in
// time and zoomed together, drawn by dygraphs (Debian's libjs-dygraphs, inlined into the page:
// dygraph.min.js, dygraph.min.css and the synchronizer extra), a summary table, and the sound
// and the vibration playable from data URIs (Ogg Vorbis: a tenth of a WAV's size). The page
// records what it has drawn in a hidden #status (for tests in a headless browser, nothing shown):
// data-drawn, the number of plots; data-plots, each plot area's rectangle, how many values it
// has and how many tick labels its axis labels overlap; data-onsets, how many onset lines of
// each drum part the waveform shows; each player's duration once loaded (data-duration). Script
// and player errors are written into #errors. Onsets are drawn in their part's colour, named in
// a legend (#onset-legend).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tactus/analysis/drum_part.hpp"

namespace tactus {

struct ReportPlot {
    std::string id, title, y_label;
    std::vector<std::string> labels;        // the series' names, after "time_s"
    std::vector<std::vector<double>> rows;  // time_s, then one value per series (NaN: a gap)
    bool log_y = false;
    bool onsets = false;                  // draw the onsets as lines under it
    bool band = false;                    // one series as min/max rows: [t, min, max]
    bool points = false;                  // draw each value as a dot (sparse series)
    std::vector<std::string> right_axis;  // series drawn against a second y axis
};

struct ReportOnset {
    double time_s = 0;
    DrumPart part = DrumPart::other;
};

struct ReportData {
    std::string title;
    std::vector<std::pair<std::string, std::string>> summary;  // (what, value) rows
    std::vector<ReportPlot> plots;
    std::vector<ReportOnset> onsets;
    std::string sound_ogg, vibration_ogg;  // Ogg Vorbis file bytes (may be empty)
    std::string note;                      // a line under the players (e.g. what was cut)
};

// Debian's dygraphs, read from $TACTUS_DYGRAPHS_DIR or /usr/share/javascript/dygraphs; throws
// std::runtime_error naming the package when it is missing.
struct Dygraphs {
    std::string script, synchronizer, style;
};
Dygraphs load_dygraphs();

std::string report_html(const ReportData& data, const Dygraphs& dygraphs);

// For the data URIs.
std::string base64(const std::string& bytes);

}  // namespace tactus
