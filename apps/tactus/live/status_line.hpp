// The terminal status line of `tactus live`: input and output levels, onsets per second, the
// callback's load, xruns and the latency, redrawn in place on stderr (a terminal only).
#pragma once

#include <string>

#include "live_callback.hpp"

namespace tactus::live {

// One line of text (no newline) for meters taken over `seconds`, `onsets` in that time.
std::string status_text(const Meters& meters, double seconds, int64_t onsets, double latency_ms);

}  // namespace tactus::live
