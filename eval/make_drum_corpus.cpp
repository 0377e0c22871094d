// make_drum_corpus OUTDIR [SEED [KIT...]]: writes the drum corpus (see drum_corpus.hpp) as float
// WAVs with ground truth beside each: NAME.wav, NAME.onsets.txt (one onset per line, seconds) and
// NAME.hits.csv (time_s,instrument,gain_db). Kits named on the command line replace Sonic Pi's:
// KIT_kick.flac, KIT_snare.flac and KIT_hat.flac in the sample directory (eval/gm_kits.py).
#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "drum_corpus.hpp"
#include "tactus/io/audio_writer.hpp"

namespace {

void write(const tactus::corpus::Track& track, const std::filesystem::path& dir) {
    tactus::AudioWriter audio(dir / (track.name + ".wav"), track.sample_rate_hz, 1);
    audio.write(track.audio.data(), static_cast<int>(track.audio.size()));
    audio.commit();
    std::ofstream onsets(dir / (track.name + ".onsets.txt"));
    for (double t : track.onsets_s) onsets << fmt::format("{:.6f}\n", t);
    std::ofstream hits(dir / (track.name + ".hits.csv"));
    hits << "time_s,instrument,gain_db\n";
    const char* names[] = {"kick", "snare", "hat"};
    for (const auto& h : track.hits)
        hits << fmt::format("{:.6f},{},{:.2f}\n", h.time_s, names[static_cast<int>(h.instrument)],
                            h.gain_db);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: make_drum_corpus OUTDIR [SEED [KIT...]]\n";
        return 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        const uint64_t seed = argc >= 3 ? std::strtoull(argv[2], nullptr, 10) : 1;
        std::filesystem::create_directories(dir);
        using namespace tactus::corpus;
        std::vector<DrumKit> named;
        for (int i = 3; i < argc; ++i)
            named.push_back({argv[i], std::string(argv[i]) + "_kick",
                             std::string(argv[i]) + "_snare", std::string(argv[i]) + "_hat"});
        uint64_t k = 0;
        for (const DrumKit& kit : named.empty() ? kits() : named) {
            ++k;
            write(breakbeat(kit, seed * 1000 + k), dir);
            write(breakbeat(kit, seed * 1000 + k, -20.0), dir);
            write(gain_series(kit, Instrument::kick, seed * 2000 + k), dir);
            write(gain_series(kit, Instrument::snare, seed * 3000 + k), dir);
        }
    } catch (const std::exception& e) {
        std::cerr << "make_drum_corpus: error: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
