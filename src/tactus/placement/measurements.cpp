#include "tactus/placement/measurements.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>
#include <tuple>

namespace tactus {
namespace {

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> fields;
    for (size_t start = 0;;) {
        const size_t comma = line.find(',', start);
        fields.push_back(trim(line.substr(start, comma - start)));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

}  // namespace

std::vector<Measurement> parse_measurements(std::istream& in, std::string_view origin) {
    const auto fail = [&](int line, const std::string& what) {
        return std::runtime_error(fmt::format("{}:{}: {}", origin, line, what));
    };
    const auto number = [&](int line, std::string_view column, std::string_view text) {
        double value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
            !std::isfinite(value))
            throw fail(line, fmt::format("{} '{}' is not a number", column, text));
        return value;
    };

    std::vector<Measurement> rows;
    std::map<std::tuple<std::string, std::string, double>, int> seen;  // -> line
    bool header = false;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        const std::string_view content = trim(text);
        if (content.empty() || content.front() == '#') continue;
        const std::vector<std::string_view> fields = split(content);
        if (!header) {
            if (fields != split(kMeasurementHeader))
                throw fail(line, fmt::format("expected the header '{}', got '{}'",
                                             kMeasurementHeader, content));
            header = true;
            continue;
        }
        if (fields.size() != 4)
            throw fail(line, fmt::format("expected 4 fields ({}), got {}", kMeasurementHeader,
                                         fields.size()));
        Measurement m{std::string(fields[0]), std::string(fields[1]),
                      number(line, "hole_mm", fields[2]), number(line, "extension_mm", fields[3]),
                      line};
        if (m.subject.empty()) throw fail(line, "subject is empty");
        if (m.finger.empty()) throw fail(line, "finger is empty");
        if (m.hole_mm <= 0) throw fail(line, fmt::format("hole_mm {} must be > 0", m.hole_mm));
        if (m.extension_mm < 0)
            throw fail(line, fmt::format("extension_mm {} must be >= 0", m.extension_mm));
        const auto [at, inserted] = seen.try_emplace({m.subject, m.finger, m.hole_mm}, line);
        if (!inserted)
            throw fail(line, fmt::format("subject {} finger {} hole {} mm was already measured "
                                         "on line {}",
                                         m.subject, m.finger, m.hole_mm, at->second));
        rows.push_back(std::move(m));
    }
    if (in.bad()) throw std::runtime_error(fmt::format("{}: read error", origin));
    if (!header)
        throw std::runtime_error(
            fmt::format("{}: no header line '{}' and no measurements", origin, kMeasurementHeader));
    if (rows.empty()) throw std::runtime_error(fmt::format("{}: no measurements", origin));
    return rows;
}

std::vector<Measurement> read_measurements(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(fmt::format("{}: cannot open", path.string()));
    return parse_measurements(in, path.string());
}

}  // namespace tactus
