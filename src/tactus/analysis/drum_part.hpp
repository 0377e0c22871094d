// The part of a drum kit an onset is heard as (real-time drum transcription's three classes,
// plus everything else a mix holds: bass, chords, voice). analysis/hit_analysis.hpp decides it.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace tactus {

enum class DrumPart : uint8_t { kick, snare, hat, other };
inline constexpr std::array<std::string_view, 4> kDrumPartNames = {"kick", "snare", "hat", "other"};
inline constexpr int kDrumParts = static_cast<int>(kDrumPartNames.size());

inline std::string_view name_of(DrumPart part) {
    return kDrumPartNames[static_cast<size_t>(part)];
}

}  // namespace tactus
