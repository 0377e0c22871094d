// Tonehole skin-extension measurements (paper §4, Figures 1 and 2): how far a fingertip pressed
// on a hole of a given diameter extends below the surround's outer surface. Read from CSV:
//   subject,finger,hole_mm,extension_mm
// one header line, then one row per subject, finger and hole; blank lines and lines starting
// with '#' are skipped. Every problem is a one-line error "file:line: what is wrong".
#pragma once

#include <filesystem>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace tactus {

struct Measurement {
    std::string subject, finger;
    double hole_mm = 0;       // hole diameter
    double extension_mm = 0;  // skin extension below the surround's outer surface
    int line = 0;             // where it was read
};

inline constexpr std::string_view kMeasurementHeader = "subject,finger,hole_mm,extension_mm";

// Throws std::runtime_error "origin:line: message" (or "origin: message").
std::vector<Measurement> parse_measurements(std::istream& in, std::string_view origin);
std::vector<Measurement> read_measurements(const std::filesystem::path& path);

}  // namespace tactus
