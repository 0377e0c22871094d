#include "tactus/export/normalisation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {

// The p-th percentile of `values`, linear between ranks (numpy.percentile's default).
double percentile_of(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    const double rank = p / 100.0 * static_cast<double>(values.size() - 1);
    const auto below = static_cast<size_t>(std::floor(rank));
    const size_t above = std::min(values.size() - 1, below + 1);
    return values[below] + (rank - static_cast<double>(below)) * (values[above] - values[below]);
}

}  // namespace

Normalisation Normalisation::parse(std::string_view text, double gain_db) {
    const auto fail = [&] {
        return std::invalid_argument(fmt::format(
            "'{}': expected peak or pNN, the NN-th percentile of the hits, NN from {:g} to 100",
            text, kLowestPercentile));
    };
    if (!(std::abs(gain_db) <= kMaxGainDb))
        throw std::invalid_argument(
            fmt::format("gain {:g} dB is out of range: allowed -{:g} to {:g} dB", gain_db,
                        kMaxGainDb, kMaxGainDb));
    Normalisation n;
    n.gain_db = gain_db;
    if (text == "peak") {
        n.reference = Reference::peak;
        return n;
    }
    if (text.size() < 2 || text[0] != 'p') throw fail();
    const char* end = text.data() + text.size();
    const auto [at, error] = std::from_chars(text.data() + 1, end, n.percentile);
    if (error != std::errc() || at != end || !(n.percentile >= kLowestPercentile) ||
        !(n.percentile <= 100))
        throw fail();
    return n;
}

std::string Normalisation::name() const {
    return reference == Reference::peak ? "peak" : fmt::format("p{:g}", percentile);
}

std::string normalisation_help() {
    return fmt::format(
        "what becomes full scale (1, 255) in .ahap, .haptic and .android.json: peak (the loudest "
        "moment) or pNN (the NN-th percentile of the hits' felt peaks, NN {:g}-100; louder "
        "moments clip at full scale; no hits: the peak). The .ogg carries the drive as rendered",
        Normalisation::kLowestPercentile);
}

void normalise(HapticTrack& track, const Normalisation& normalisation) {
    std::vector<double> hits;
    for (const HapticOnset& onset : track.onsets) hits.push_back(onset.intensity);
    const bool by_hits =
        normalisation.reference == Normalisation::Reference::percentile && !hits.empty();
    double reference = 1.0;  // the track as rendered: 1 is its peak
    if (by_hits) reference = percentile_of(hits, normalisation.percentile);
    if (!(reference > 0)) reference = 1.0;  // silent hits: nothing to scale to
    const double factor = db_to_gain(normalisation.gain_db) / reference;
    size_t clipped = 0;
    for (double& v : track.intensity) {
        clipped += v * factor > 1.0;
        v = std::min(1.0, v * factor);
    }
    for (HapticOnset& onset : track.onsets)
        onset.intensity = std::min(1.0, onset.intensity * factor);
    track.felt_full_scale /= factor;
    const std::string what =
        by_hits ? fmt::format("{} of the hits' felt peaks ({} hits; {:.3f} of the peak)",
                              normalisation.name(), hits.size(), reference)
        : normalisation.reference == Normalisation::Reference::peak
            ? "the peak"
            : fmt::format("the peak (no hits for {})", normalisation.name());
    track.normalisation = fmt::format(
        "{} is full scale, gain {:+.1f} dB; {:.1f} % of the time clipped", what,
        normalisation.gain_db,
        track.intensity.empty()
            ? 0.0
            : 100.0 * static_cast<double>(clipped) / static_cast<double>(track.intensity.size()));
}

}  // namespace tactus
