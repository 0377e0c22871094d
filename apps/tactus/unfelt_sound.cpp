#include "unfelt_sound.hpp"

#include <fmt/format.h>

namespace tactus::cli {

std::string UnfeltSound::warning(const std::string& input, double sample_rate_hz) const {
    // A drone or a tone that fades in has no onset: a preset that pulses only at onsets leaves it
    // silent. Say so rather than hand back digital silence without a word.
    if (peak_ == 0 && loudest_db_ > gate_db_)
        return fmt::format(
            "tactus: warning: {}: the input is audible (loudness up to {:.0f} dB) but gave no "
            "vibration: it has no onset for the pulses; for sustained sounds try --preset "
            "sustained",
            input, loudest_db_);
    // A sustained sound after its onset (an explosion's rumble) gets one pulse from a preset of
    // discrete pulses, and then nothing: one line per file, naming the longest such stretch.
    const double unfelt_s = static_cast<double>(longest_frames_) / sample_rate_hz;
    if (unfelt_s >= kLongStretchS && !sustains_)
        return fmt::format(
            "tactus: warning: {}: {:.1f} s of sound from {:.1f} s on gave no vibration: the "
            "preset pulses only at onsets; for sustained sounds try --preset sustained",
            input, unfelt_s, static_cast<double>(longest_start_) / sample_rate_hz);
    return {};
}

}  // namespace tactus::cli
