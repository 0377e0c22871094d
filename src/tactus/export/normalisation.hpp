// How a haptic export scales the felt envelope to the platform's 0 ... 1: a reference level read
// from the track becomes full scale, a gain is applied, and anything above 1 clips at 1.
//   peak   the envelope's loudest moment: one hit can set every other hit's level.
//   pNN    the NN-th percentile (50 ... 100) of the hits' felt peaks (the transients'
//          intensities; linear between ranks, as numpy.percentile): the loudest (100 - NN) %
//          of hits clip, the rest keep their proportions. A track without hits uses its peak.
// The reference is felt amplitude, so a percentile of hits follows what is felt, not the drive.
// Offline (file exports); the formats state what was done in their metadata.
#pragma once

#include <string>
#include <string_view>

#include "tactus/export/haptic_track.hpp"

namespace tactus {

struct Normalisation {
    enum class Reference { peak, percentile };
    static constexpr double kLowestPercentile = 50;
    static constexpr double kMaxGainDb = 40;  // either way: beyond, everything clips or vanishes

    Reference reference = Reference::percentile;
    double percentile = 99;
    double gain_db = 0;

    // "peak" or "pNN" (NN: 50 ... 100, decimals allowed); throws std::invalid_argument with a
    // one-line reason that quotes `text`.
    static Normalisation parse(std::string_view text, double gain_db = 0);
    std::string name() const;  // "peak", "p99", "p99.5"
};

// What the exports' option says (the reference's forms and the default), for its help.
std::string normalisation_help();

// Scales the track's intensity and its onsets' intensities (clipped at 1), sets felt_full_scale
// to the felt amplitude now at 1, and says in track.normalisation what was done (one line).
void normalise(HapticTrack& track, const Normalisation& normalisation);

}  // namespace tactus
