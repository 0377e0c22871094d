#include "tactus/perception/sensation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "tactus/core/units.hpp"

namespace tactus::perception {

double combined_sensation_db(const ChannelLevels& sensation_levels_db) {
    ChannelLevels magnitude{};
    for (size_t c = 0; c < magnitude.size(); ++c)
        magnitude[c] = db_to_gain(kMagnitudeExponent * std::max(0.0, sensation_levels_db[c])) - 1.0;
    std::sort(magnitude.begin(), magnitude.end(), std::greater<>());
    double total = magnitude[0];
    for (size_t c = 1; c < magnitude.size(); ++c) total += kWeakerChannelWeight * magnitude[c];
    return 20.0 / kMagnitudeExponent * std::log10(1.0 + total);
}

}  // namespace tactus::perception
