// A drum corpus with exact ground truth, built from Sonic Pi's single drum hits (Debian package
// sonic-pi-samples): breakbeat patterns at random tempi (fixed seed), with and without noise,
// and isolated kick / snare hits over a 24 dB range of gains. Used by the end-to-end tests and by
// eval/evaluate.py (through make_drum_corpus).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tactus::corpus {

enum class Instrument { kick, snare, hat };

struct DrumKit {
    std::string name;
    std::string kick, snare, hat;  // sample names without extension
};

struct Hit {
    double time_s;
    Instrument instrument;
    double gain_db;
};

struct Track {
    std::string name;
    double sample_rate_hz = 44100;
    std::vector<float> audio;
    std::vector<Hit> hits;         // every hit placed
    std::vector<double> onsets_s;  // ground truth: distinct hit times, ascending
};

std::filesystem::path sample_directory();  // $TACTUS_SAMPLES or /usr/share/sonic-pi/samples
const std::vector<DrumKit>& kits();

// Four bars of a breakbeat: kick, snare (with ghost notes) and hats on a 16th grid.
// noise_db: white noise at this level relative to the music's RMS (e.g. -20); 0 = none.
Track breakbeat(const DrumKit& kit, uint64_t seed, double noise_db = 0);
// One instrument alone, 9 hits at gains 0, -3, ... -24 dB (shuffled), 1 s apart.
Track gain_series(const DrumKit& kit, Instrument instrument, uint64_t seed);

// Onset F-measure with one-to-one matching within +-tolerance (maximum bipartite matching, as
// mir_eval.onset.f_measure does).
struct OnsetScore {
    double f_measure, precision, recall;
    int matched;
};
OnsetScore score_onsets(const std::vector<double>& reference_s,
                        const std::vector<double>& estimated_s, double tolerance_s = 0.05);

}  // namespace tactus::corpus
