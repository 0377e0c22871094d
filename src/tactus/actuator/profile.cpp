#include "tactus/actuator/profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tactus/core/units.hpp"

namespace tactus {

double interpolate_db(const std::vector<std::pair<double, double>>& points, double f) {
    if (points.empty()) return 0.0;
    if (f <= points.front().first) return points.front().second;
    if (f >= points.back().first) return points.back().second;
    const auto above = std::upper_bound(points.begin(), points.end(), f,
                                        [](double x, const auto& p) { return x < p.first; });
    const auto below = above - 1;
    const double t = std::log(f / below->first) / std::log(above->first / below->first);
    return below->second + t * (above->second - below->second);
}

std::string_view type_name(ActuatorType type) {
    return kActuatorTypeNames[static_cast<int>(type)];
}

double ActuatorProfile::response_db(double frequency_hz) const {
    const auto shape_db = [&](double f) {
        double db = interpolate_db(points, f);
        const double x = f / resonance_hz;
        if (resonance == ResonanceKind::low_pass)
            db -= 10.0 * std::log10((1 - x * x) * (1 - x * x) + x * x / (q * q));
        else if (resonance == ResonanceKind::band_pass)
            db -= 10.0 * std::log10(1 + q * q * (x - 1 / x) * (x - 1 / x));
        return db;
    };
    if (frequency_hz <= 0 && !dc) return -std::numeric_limits<double>::infinity();
    double db = shape_db(std::max(frequency_hz, 0.0)) - shape_db(reference_hz);
    if (!dc && frequency_hz < band_low_hz)
        db -= rolloff_db_per_octave * std::log2(band_low_hz / frequency_hz);
    if (frequency_hz > band_high_hz)
        db -= rolloff_db_per_octave * std::log2(frequency_hz / band_high_hz);
    return db;
}

double ActuatorProfile::displacement_um_at(double frequency_hz) const {
    return displacement_um * db_to_gain(response_db(frequency_hz));
}

}  // namespace tactus
