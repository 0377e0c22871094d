#include "tactus/export/html_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace tactus {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr const char* kDygraphsDir = "/usr/share/javascript/dygraphs";  // libjs-dygraphs

// Each drum part's onset colour, in kDrumPartNames' order: hues apart from one another and from
// the series' (dygraphs' own, half-bright hues), so neither hides the other.
constexpr std::array<const char*, kDrumParts> kPartColours = {"#d62728", "#2864ff", "#e6aa00",
                                                              "#787878"};

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(
            fmt::format("{}: cannot read dygraphs (install Debian's libjs-dygraphs, or set "
                        "TACTUS_DYGRAPHS_DIR)",
                        path.string()));
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Inlined text must not end the element it sits in, nor ask for a source map over the network.
std::string inlined(std::string text, const std::string& closing_tag) {
    for (size_t at; (at = text.find("//# sourceMappingURL=")) != std::string::npos;)
        text.erase(at, text.find('\n', at) == std::string::npos ? std::string::npos
                                                                : text.find('\n', at) - at);
    for (size_t at = 0; (at = text.find(closing_tag, at)) != std::string::npos;)
        text.replace(at, 2, "<\\/");
    return text;
}

std::string escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '&':
                out += "&amp;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

// Numbers as the plots need them: 5 significant digits, NaN as null (a gap).
Json number(double x) {
    if (!std::isfinite(x)) return nullptr;
    return std::stod(fmt::format("{:.5g}", x));
}

constexpr const char* kScript = R"JS(
window.onerror = function (message, source, line) {
  document.getElementById('errors').textContent += message + ' (line ' + line + ')\n';
};
document.querySelectorAll('audio').forEach(function (audio) {
  var loaded = function () { audio.setAttribute('data-duration', String(audio.duration)); };
  var failed = function () {
    document.getElementById('errors').textContent +=
        'the ' + audio.getAttribute('data-label') + ' player cannot play its sound\n';
  };
  audio.addEventListener('loadedmetadata', loaded);
  audio.addEventListener('error', failed);
  if (audio.error) failed();
  else if (audio.readyState >= 1) loaded();  // loaded before this script ran
});
// How many tick labels a plot's axis titles run into: a title's text, as laid out, must stay
// clear of its axis's column (or row) of tick labels (a title that wraps runs into it).
function textRects(element) {
  var range = document.createRange();
  range.selectNodeContents(element);
  return Array.prototype.slice.call(range.getClientRects());
}
function labelOverlaps(div) {
  var count = 0;
  [['ylabel', 'y', true], ['y2label', 'y2', true], ['xlabel', 'x', false]].forEach(function (a) {
    var ticks = [];
    div.querySelectorAll('.dygraph-axis-label-' + a[1]).forEach(function (t) {
      ticks = ticks.concat(textRects(t));
    });
    div.querySelectorAll('.dygraph-' + a[0]).forEach(function (title) {
      textRects(title).forEach(function (r) {
        ticks.forEach(function (t) {
          if (a[2] ? r.left < t.right && t.left < r.right : r.top < t.bottom && t.top < r.bottom)
            ++count;
        });
      });
    });
  });
  return count;
}
var kTickWidth = 64;  // px
(function () {
  var plots = JSON.parse(document.getElementById('plot-data').textContent);
  var onsets = JSON.parse(document.getElementById('onset-data').textContent);
  var graphs = [], shown = {};  // shown: onset lines per part in the waveform, as last drawn
  // Every plot shows the same time span from the start (the synchronizer keeps it so on zoom).
  var end = 0;
  plots.forEach(function (p) { if (p.rows.length) end = Math.max(end, p.rows[p.rows.length - 1][0]); });
  plots.forEach(function (p) {
    var series = {};
    (p.right || []).forEach(function (name) { series[name] = {axis: 'y2'}; });
    var data = p.rows;
    if (p.band) data = p.rows.map(function (r) { return [r[0], [r[1], (r[1] + r[2]) / 2, r[2]]]; });
    var options = {
      labels: ['time_s'].concat(p.labels), title: p.title, ylabel: p.ylabel, xlabel: 'time (s)',
      logscale: p.log, customBars: p.band, fillAlpha: 0.6, series: series,
      connectSeparatedPoints: false, legend: 'always', labelsSeparateLines: false,
      labelsDiv: document.getElementById(p.id + '-legend'),
      // Room for five-digit ticks (10000 Hz) beside the axis title: dygraphs' 50 px lets a
      // title touch four-digit ones.
      axes: {y: {axisLabelWidth: kTickWidth},
             y2: {independentTicks: true, axisLabelWidth: kTickWidth}},
      height: 180, animatedZooms: false,
      dateWindow: [0, end], drawPoints: p.points, pointSize: 3
    };
    if (p.right && p.right.length) options.y2label = p.right.join(', ');
    if (p.onsets) options.underlayCallback = function (ctx, area, g) {
      var counts = {};
      onsets.names.forEach(function (name) { counts[name] = 0; });
      ctx.save();
      ctx.globalAlpha = 0.7;
      ctx.lineWidth = 1;
      onsets.times.forEach(function (t, i) {
        var x = g.toDomXCoord(t), part = onsets.parts[i];
        if (x < area.x || x > area.x + area.w) return;
        ctx.strokeStyle = onsets.colours[part];
        ctx.beginPath(); ctx.moveTo(x, area.y); ctx.lineTo(x, area.y + area.h); ctx.stroke();
        ++counts[onsets.names[part]];
      });
      ctx.restore();
      if (p.id === 'waveform') shown = counts;
    };
    graphs.push(new Dygraph(document.getElementById(p.id), data, options));
  });
  if (graphs.length > 1) Dygraph.synchronize(graphs, {zoom: true, selection: true, range: false});
  var areas = graphs.map(function (g, i) {
    var box = g.graphDiv.getBoundingClientRect(), a = g.getArea(), values = 0;
    plots[i].rows.forEach(function (r) {
      for (var k = 1; k < r.length; ++k) if (r[k] !== null) { ++values; break; }
    });
    return {id: plots[i].id, x: Math.round(box.left + a.x + window.scrollX),
            y: Math.round(box.top + a.y + window.scrollY), w: Math.round(a.w), h: Math.round(a.h),
            values: values, overlaps: labelOverlaps(g.graphDiv)};
  });
  var status = document.getElementById('status');
  status.setAttribute('data-plots', JSON.stringify(areas));
  status.setAttribute('data-onsets', JSON.stringify(shown));
  status.setAttribute('data-drawn', String(graphs.length));
})();
)JS";

}  // namespace

Dygraphs load_dygraphs() {
    const char* env = std::getenv("TACTUS_DYGRAPHS_DIR");
    const fs::path dir = env && *env ? fs::path(env) : fs::path(kDygraphsDir);
    return {read_text(dir / "dygraph.min.js"), read_text(dir / "extras" / "synchronizer.js"),
            read_text(dir / "dygraph.min.css")};
}

std::string base64(const std::string& bytes) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = static_cast<uint8_t>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) v |= static_cast<uint8_t>(bytes[i + 2]);
        out += kDigits[(v >> 18) & 63];
        out += kDigits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
    }
    return out;
}

std::string report_html(const ReportData& data, const Dygraphs& dygraphs) {
    Json plots = Json::array();
    std::string divs;
    for (const ReportPlot& p : data.plots) {
        Json rows = Json::array();
        for (const auto& row : p.rows) {
            Json r = Json::array();
            for (const double x : row) r.push_back(number(x));
            rows.push_back(std::move(r));
        }
        plots.push_back({{"id", p.id},
                         {"title", p.title},
                         {"ylabel", p.y_label},
                         {"labels", p.labels},
                         {"rows", std::move(rows)},
                         {"log", p.log_y},
                         {"onsets", p.onsets},
                         {"band", p.band},
                         {"points", p.points},
                         {"right", p.right_axis}});
        divs += fmt::format(
            "<div class=\"legend\" id=\"{0}-legend\"></div>\n"
            "<div class=\"plot\" id=\"{0}\"></div>\n",
            p.id);
    }
    // Onsets as parallel arrays (time, part's index), and a legend: each part's colour and count.
    Json times = Json::array(), parts = Json::array();
    std::array<int, kDrumParts> count{};
    for (const ReportOnset& o : data.onsets) {
        times.push_back(number(o.time_s));
        parts.push_back(static_cast<int>(o.part));
        ++count[static_cast<size_t>(o.part)];
    }
    Json names = Json::array(), colours = Json::array();
    for (size_t i = 0; i < kDrumPartNames.size(); ++i) {
        names.push_back(std::string(kDrumPartNames[i]));
        colours.push_back(kPartColours[i]);
    }
    const Json onsets = {
        {"times", times}, {"parts", parts}, {"names", names}, {"colours", colours}};
    std::string legend;
    for (size_t i = 0; i < kDrumPartNames.size(); ++i)
        legend += fmt::format(
            " <span class=\"onset-part\" data-part=\"{0}\" data-colour=\"{1}\" "
            "style=\"color: {1}\">&#9475; {0}</span> ({2})",
            kDrumPartNames[i], kPartColours[i], count[i]);
    std::string summary;
    for (const auto& [what, value] : data.summary)
        summary += fmt::format("<tr><th>{}</th><td>{}</td></tr>\n", escaped(what), escaped(value));
    const auto player = [](const char* label, const std::string& ogg) {
        if (ogg.empty()) return std::string();
        return fmt::format(
            "<p><span>{0}</span><audio controls data-label=\"{0}\" "
            "src=\"data:audio/ogg;base64,{1}\"></audio></p>\n",
            label, base64(ogg));
    };
    std::string page;
    page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    page += fmt::format("<title>{}</title>\n", escaped(data.title));
    page += "<style>\n" + inlined(dygraphs.style, "</style") + "\n</style>\n";
    page += R"(<style>
body { font-family: sans-serif; margin: 16px 24px; max-width: 1400px; }
table { border-collapse: collapse; margin-bottom: 12px; }
th, td { text-align: left; padding: 2px 12px 2px 0; font-size: 13px; }
.plot { width: 100%; height: 180px; margin: 0 0 18px 0; }
.legend { font-size: 12px; height: 16px; margin-left: 80px; }
audio { vertical-align: middle; margin-left: 8px; width: 480px; }
#errors { color: #b00; white-space: pre; }
.dygraph-title { font-size: 14px; }
</style>
</head>
<body>
)";
    page += fmt::format("<h1>{}</h1>\n<table>\n{}</table>\n", escaped(data.title), summary);
    page += player("sound", data.sound_ogg) + player("vibration", data.vibration_ogg);
    if (!data.note.empty()) page += fmt::format("<p><small>{}</small></p>\n", escaped(data.note));
    page += "<p><small>Drag to zoom (every plot follows), double-click to zoom out.</small></p>\n";
    page += "<p id=\"onset-legend\"><small>Onsets by drum part:" + legend + "</small></p>\n";
    page += "<div id=\"status\" hidden></div><div id=\"errors\"></div>\n";
    page += divs;
    page += "<script type=\"application/json\" id=\"plot-data\">" +
            inlined(plots.dump(), "</script") + "</script>\n";
    page += "<script type=\"application/json\" id=\"onset-data\">" + onsets.dump() + "</script>\n";
    page += "<script>\n" + inlined(dygraphs.script, "</script") + "\n</script>\n";
    page += "<script>\n" + inlined(dygraphs.synchronizer, "</script") + "\n</script>\n";
    page += std::string("<script>\n") + kScript + "</script>\n</body>\n</html>\n";
    return page;
}

}  // namespace tactus
