// A self-contained HTML report (one file, no network: opened by double click): plots aligned in
// time and zoomed together, drawn by dygraphs (Debian's libjs-dygraphs, inlined into the page:
// dygraph.min.js, dygraph.min.css and the synchronizer extra), a summary table, and the sound
// and the vibration playable from data URIs. The page records that it has drawn: its title
// becomes "tactus report: drawn" and #status carries each plot area's rectangle and how many
// values it has, and how many onset lines of each drum part the waveform shows (for tests in a
// headless browser); script errors are written into #errors. Onsets are drawn in their part's
// colour, named in a legend (#onset-legend).
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
    std::string sound_wav, vibration_wav;  // file bytes (may be empty)
    std::string note;                      // a line under the players (e.g. what was cut)
};

// Debian's dygraphs, read from $TACTUS_DYGRAPHS_DIR or /usr/share/javascript/dygraphs; throws
// std::runtime_error naming the package when it is missing.
struct Dygraphs {
    std::string script, synchronizer, style;
};
Dygraphs load_dygraphs();

std::string report_html(const ReportData& data, const Dygraphs& dygraphs);

// Helpers for the data URIs: a 16-bit mono WAV file in memory, and base64.
std::string wav_file_bytes(const std::vector<float>& mono, double sample_rate_hz);
std::string base64(const std::string& bytes);

}  // namespace tactus
