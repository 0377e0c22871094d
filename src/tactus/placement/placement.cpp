#include "tactus/placement/placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

namespace tactus {

PlacementReport summarise_placement(std::span<const Measurement> measurements) {
    std::map<double, std::vector<const Measurement*>> by_hole;
    for (const Measurement& m : measurements) by_hole[m.hole_mm].push_back(&m);

    PlacementReport report;
    for (const auto& [hole_mm, rows] : by_hole) {
        HoleSummary h;
        h.hole_mm = hole_mm;
        h.n = static_cast<int>(rows.size());
        std::set<std::string> subjects;
        double sum = 0;
        h.min_mm = std::numeric_limits<double>::infinity();
        h.max_mm = -h.min_mm;
        for (const Measurement* m : rows) {
            subjects.insert(m->subject);
            sum += m->extension_mm;
            h.min_mm = std::min(h.min_mm, m->extension_mm);
            h.max_mm = std::max(h.max_mm, m->extension_mm);
        }
        h.subjects = static_cast<int>(subjects.size());
        h.mean_mm = sum / h.n;
        double squares = 0;
        for (const Measurement* m : rows) squares += std::pow(m->extension_mm - h.mean_mm, 2);
        h.sd_mm =
            h.n >= 2 ? std::sqrt(squares / (h.n - 1)) : std::numeric_limits<double>::quiet_NaN();
        h.depth_mm = h.n >= 2 ? std::max(0.0, h.mean_mm - h.sd_mm) : h.mean_mm;
        report.holes.push_back(h);
    }
    for (size_t i = 0; i < report.holes.size(); ++i) {
        const HoleSummary& h = report.holes[i];
        if (h.n < 2) continue;
        if (!report.least_variation || h.sd_mm < report.holes[*report.least_variation].sd_mm)
            report.least_variation = i;
    }
    return report;
}

}  // namespace tactus
