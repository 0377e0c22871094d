// A digest of what one of a render's plots draws (its rows, bit for bit, its labels and flags,
// and the onsets when it draws them), so that the page, which sends back the digests of the
// plots it holds, is sent only the plots a change changed: a live setting leaves the sound's
// waveform and its features as they were. Any thread.
#pragma once

#include <string>
#include <vector>

#include "tactus/export/html_report.hpp"

namespace tactus::cli {

// 16 hex digits (64-bit FNV-1a): a different plot has the same digest once in 2^64.
std::string plot_digest(const ReportPlot& plot, const std::vector<ReportOnset>& onsets);

}  // namespace tactus::cli
