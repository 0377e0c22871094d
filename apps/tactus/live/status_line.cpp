#include "status_line.hpp"

#include <fmt/format.h>

#include <cmath>

#include "tactus/core/units.hpp"

namespace tactus::live {
namespace {

std::string level(float peak) {
    return peak > 0 ? fmt::format("{:6.1f} dBFS", gain_to_db(peak)) : std::string("  -inf dBFS");
}

}  // namespace

std::string status_text(const Meters& meters, double seconds, int64_t onsets, double latency_ms) {
    return fmt::format(
        "in {}  out {}  onsets {:4.1f}/s  load {:3.0f} %  xruns {}  latency {:.1f} ms",
        level(meters.input_peak), level(meters.output_peak), seconds > 0 ? onsets / seconds : 0.0,
        100 * meters.load, meters.xruns, latency_ms);
}

}  // namespace tactus::live
