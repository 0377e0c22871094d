#include "drum_corpus.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <numeric>
#include <stdexcept>

#include "tactus/io/audio_reader.hpp"

namespace tactus::corpus {
namespace {

// Deterministic on every platform: no std:: distributions (their output is unspecified).
class Random {
  public:
    explicit Random(uint64_t seed) : state_(seed ^ 0x9E3779B97F4A7C15ull) {}
    uint64_t next() {  // splitmix64
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    bool chance(double p) { return uniform() < p; }
    double gaussian() {
        const double u = std::max(uniform(), 1e-300), v = uniform();
        return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * 3.14159265358979323846 * v);
    }

  private:
    uint64_t state_;
};

// A sample, trimmed so that it starts at its onset (first sample above -40 dB of its peak).
const std::vector<float>& load(const std::string& name) {
    static std::map<std::string, std::vector<float>> cache;
    auto found = cache.find(name);
    if (found != cache.end()) return found->second;
    std::vector<float> audio = read_mono(sample_directory() / (name + ".flac")).samples;
    float peak = 0;
    for (float x : audio) peak = std::max(peak, std::abs(x));
    const auto start = std::find_if(audio.begin(), audio.end(),
                                    [&](float x) { return std::abs(x) > 0.01f * peak; });
    audio.erase(audio.begin(), start);
    for (float& x : audio) x /= peak;  // every sample peaks at 1 before its gain
    return cache.emplace(name, std::move(audio)).first->second;
}

const std::string& sample_of(const DrumKit& kit, Instrument instrument) {
    switch (instrument) {
        case Instrument::kick:
            return kit.kick;
        case Instrument::snare:
            return kit.snare;
        case Instrument::hat:
            break;
    }
    return kit.hat;
}

void place(std::vector<float>& mix, const std::vector<float>& sample, double time_s, double gain_db,
           double sample_rate_hz) {
    const auto start = static_cast<size_t>(std::llround(time_s * sample_rate_hz));
    const float gain = static_cast<float>(std::pow(10.0, gain_db / 20.0));
    if (mix.size() < start + sample.size()) mix.resize(start + sample.size(), 0.0f);
    for (size_t i = 0; i < sample.size(); ++i) mix[start + i] += gain * sample[i];
}

Track render(std::string name, const DrumKit& kit, std::vector<Hit> hits, double tail_s) {
    Track track;
    track.name = std::move(name);
    std::sort(hits.begin(), hits.end(),
              [](const Hit& a, const Hit& b) { return a.time_s < b.time_s; });
    for (const Hit& h : hits) {
        place(track.audio, load(sample_of(kit, h.instrument)), h.time_s, h.gain_db,
              track.sample_rate_hz);
        if (track.onsets_s.empty() || h.time_s - track.onsets_s.back() > 1e-6)
            track.onsets_s.push_back(h.time_s);
    }
    track.audio.resize(track.audio.size() + static_cast<size_t>(tail_s * track.sample_rate_hz),
                       0.0f);
    track.hits = std::move(hits);
    return track;
}

void normalise_peak(std::vector<float>& audio, float peak_target) {
    float peak = 0;
    for (float x : audio) peak = std::max(peak, std::abs(x));
    if (peak > 0)
        for (float& x : audio) x *= peak_target / peak;
}

}  // namespace

std::filesystem::path sample_directory() {
    if (const char* dir = std::getenv("TACTUS_SAMPLES")) return dir;
    return "/usr/share/sonic-pi/samples";
}

const std::vector<DrumKit>& kits() {
    static const std::vector<DrumKit> all = {
        {"acoustic", "drum_heavy_kick", "drum_snare_hard", "drum_cymbal_closed"},
        {"acoustic-soft", "drum_bass_hard", "drum_snare_soft", "drum_cymbal_pedal"},
        {"808", "bd_808", "sn_dolf", "drum_cymbal_closed"},
        {"house", "bd_haus", "sn_generic", "elec_tick"},
        {"electro", "elec_hollow_kick", "elec_snare", "drum_cymbal_closed"},
        {"tek", "bd_tek", "elec_hi_snare", "drum_cymbal_pedal"},
        {"fat", "bd_fat", "sn_dub", "drum_cymbal_closed"},
        {"zome", "bd_zome", "sn_zome", "elec_tick"},
    };
    return all;
}

Track breakbeat(const DrumKit& kit, uint64_t seed, double noise_db) {
    Random random(seed);
    const double tempo_bpm = random.uniform(85.0, 165.0);
    const double step_s = 60.0 / tempo_bpm / 4.0;  // 16th notes
    constexpr int kBars = 4, kSteps = 16;
    std::vector<Hit> hits;
    const double lead_s = 0.25;
    for (int bar = 0; bar < kBars; ++bar) {
        for (int step = 0; step < kSteps; ++step) {
            const double t = lead_s + (bar * kSteps + step) * step_s;
            const bool backbeat = step == 4 || step == 12;
            if (step == 0 || ((step == 6 || step == 8 || step == 10 || step == 11 || step == 14) &&
                              random.chance(0.35)))
                hits.push_back({t, Instrument::kick, random.uniform(-3.0, 0.0)});
            if (backbeat)
                hits.push_back({t, Instrument::snare, random.uniform(-3.0, 0.0)});
            else if (step % 2 == 1 && random.chance(0.12))
                hits.push_back({t, Instrument::snare, random.uniform(-14.0, -8.0)});  // ghost
            if (step % 2 == 0 && random.chance(0.8))
                hits.push_back({t, Instrument::hat, random.uniform(-12.0, -6.0)});
        }
    }
    Track track = render("breakbeat-" + kit.name, kit, std::move(hits), 0.5);
    if (noise_db != 0) {
        double energy = 0;
        for (float x : track.audio) energy += double(x) * x;
        const double noise_rms =
            std::sqrt(energy / track.audio.size()) * std::pow(10.0, noise_db / 20.0);
        for (float& x : track.audio) x += static_cast<float>(noise_rms * random.gaussian());
        track.name += "-noise";
    }
    normalise_peak(track.audio, 0.9f);
    return track;
}

Track gain_series(const DrumKit& kit, Instrument instrument, uint64_t seed) {
    Random random(seed);
    std::vector<double> gains;
    for (int g = 0; g >= -24; g -= 3) gains.push_back(g);
    for (size_t i = gains.size() - 1; i > 0; --i)  // Fisher-Yates
        std::swap(gains[i], gains[static_cast<size_t>(random.uniform() * (i + 1))]);
    std::vector<Hit> hits;
    for (size_t i = 0; i < gains.size(); ++i)
        hits.push_back({0.25 + static_cast<double>(i), instrument, gains[i] - 1.0});
    const char* names[] = {"kick", "snare", "hat"};
    return render("gain-" + kit.name + "-" + names[static_cast<int>(instrument)], kit,
                  std::move(hits), 1.0);
}

OnsetScore score_onsets(const std::vector<double>& reference, const std::vector<double>& estimated,
                        double tolerance_s) {
    // Kuhn's augmenting paths over the pairs within tolerance.
    std::vector<std::vector<int>> candidates(reference.size());
    for (size_t r = 0; r < reference.size(); ++r)
        for (size_t e = 0; e < estimated.size(); ++e)
            if (std::abs(reference[r] - estimated[e]) <= tolerance_s)
                candidates[r].push_back(static_cast<int>(e));
    std::vector<int> owner(estimated.size(), -1);
    std::function<bool(int, std::vector<char>&)> augment = [&](int r, std::vector<char>& seen) {
        for (int e : candidates[r]) {
            if (seen[e]) continue;
            seen[e] = 1;
            if (owner[e] < 0 || augment(owner[e], seen)) {
                owner[e] = r;
                return true;
            }
        }
        return false;
    };
    int matched = 0;
    for (size_t r = 0; r < reference.size(); ++r) {
        std::vector<char> seen(estimated.size(), 0);
        matched += augment(static_cast<int>(r), seen);
    }
    const double precision = estimated.empty() ? 0.0 : double(matched) / estimated.size();
    const double recall = reference.empty() ? 0.0 : double(matched) / reference.size();
    const double f = precision + recall > 0 ? 2 * precision * recall / (precision + recall) : 0.0;
    return {f, precision, recall, matched};
}

}  // namespace tactus::corpus
