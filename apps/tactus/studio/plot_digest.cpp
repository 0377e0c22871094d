#include "plot_digest.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>

namespace tactus::cli {
namespace {

struct Fnv1a {
    uint64_t state = 14695981039346656037ull;
    void add(const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) state = (state ^ bytes[i]) * 1099511628211ull;
    }
    void add(double value) { add(&value, sizeof value); }
    void add(const std::string& text) {
        add(static_cast<double>(text.size()));
        add(text.data(), text.size());
    }
};

}  // namespace

std::string plot_digest(const ReportPlot& plot, const std::vector<ReportOnset>& onsets) {
    Fnv1a h;
    for (const std::string* text : {&plot.id, &plot.title, &plot.y_label}) h.add(*text);
    for (const auto& label : plot.labels) h.add(label);
    for (const auto& label : plot.right_axis) h.add("right:" + label);
    h.add(static_cast<double>(plot.log_y + 2 * plot.onsets + 4 * plot.band + 8 * plot.points));
    h.add(static_cast<double>(plot.rows.size()));
    for (const auto& row : plot.rows) {
        h.add(static_cast<double>(row.size()));
        h.add(row.data(), row.size() * sizeof(double));
    }
    if (plot.onsets) {
        h.add(static_cast<double>(onsets.size()));
        for (const ReportOnset& o : onsets) {
            h.add(o.time_s);
            h.add(static_cast<double>(o.part));
        }
    }
    return fmt::format("{:016x}", h.state);
}

}  // namespace tactus::cli
