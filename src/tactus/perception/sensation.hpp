// Above threshold: sensation level, sensation magnitude and how channels combine.
// - Sensation level (dB SL) of a channel: stimulus level minus that channel's threshold, 0 when
//   below it ("not engaged"); channels are independent (Gescheider et al. 2004).
// - Sensation magnitude grows as a power of displacement, exponent ~0.89 up to 350 Hz
//   (Verrillo 1970): psi = 10^(0.89 SL / 20) - 1, counted from threshold.
// - Perceived intensity of a stimulus engaging several channels ~ stronger channel + 1/2 weaker
//   (Hollins & Roy 1996); with more than two, each weaker channel adds half its magnitude
//   [assumed generalisation]. Reported back on the dB SL scale of a single channel.
// - Equal-sensation contours flatten as level rises (Verrillo, Fraioli & Smith 1969 [recalled]);
//   modelled as the P threshold relief shrinking linearly with level, flat at kContourFlatDb
//   [assumed form and level]. The paper (section 5.1) holds that P's U-shape does not flatten:
//   level 0 (threshold) is that view.
#pragma once

#include <algorithm>
#include <array>

#include "tactus/perception/threshold.hpp"

namespace tactus::perception {

constexpr double kMagnitudeExponent = 0.89;   // Verrillo 1970 [read]
constexpr double kWeakerChannelWeight = 0.5;  // Hollins & Roy 1996 [read]
constexpr double kContourFlatDb = 70.0;       // SL at which contours would be flat [assumed]

using ChannelLevels = std::array<double, kChannels.size()>;  // indexed by Channel

// max(0, level - threshold).
inline double sensation_level_db(double level_db, double threshold_db) {
    return level_db > threshold_db ? level_db - threshold_db : 0.0;
}

// Combined perceived intensity of channel sensation levels, as a single-channel dB SL.
double combined_sensation_db(const ChannelLevels& sensation_levels_db);

// Fraction of the threshold curve's relief an equal-sensation contour keeps at `level_db` SL:
// contour(f, L) - contour(g, L) = (T(f) - T(g)) (1 - L / kContourFlatDb), L clamped to
// [0, kContourFlatDb].
inline double contour_relief_fraction(double level_db) {
    return 1.0 - std::clamp(level_db / kContourFlatDb, 0.0, 1.0);
}

}  // namespace tactus::perception
