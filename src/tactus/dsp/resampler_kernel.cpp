#include "tactus/dsp/resampler_kernel.hpp"

#include <cmath>
#include <numeric>

#include "tactus/core/units.hpp"
#include "tactus/dsp/fir_design.hpp"

namespace tactus {
namespace {

constexpr int kPointsPerOutput = 64;  // kernel table resolution; linear interpolation between
constexpr int kFftSize = 1 << 16;     // cepstrum length: ~28 times the kernel, little aliasing
// Band::listening: the table's linear interpolation and the tail's end under its stop band
// (64 points leave images near -70 dB), with the cepstrum as much longer than the kernel.
constexpr int kListeningPointsPerOutput = 256;
constexpr int kListeningFftSize = 1 << 19;
constexpr double kListeningTailEnergy = 1e-11;
constexpr double kFloorDb = -140;     // log-magnitude floor of the stop band's nulls
constexpr double kTailEnergy = 1e-8;  // the minimum-phase kernel ends where less is left

ResamplerKernel design_kernel(double pass_edge, double stop_edge, double stop_band_db,
                              int points_per_unit, int fft_size, double tail_energy) {
    const double transition = stop_edge - pass_edge;  // cycles/sample
    const double cutoff = 0.5 * (stop_edge + pass_edge);
    const double beta = 0.1102 * (stop_band_db - 8.7);
    const double length = (stop_band_db - 8) / (2.285 * 2 * kPi * transition);
    const int half = static_cast<int>(std::ceil(0.5 * length * points_per_unit));
    std::vector<double> h(static_cast<size_t>(2 * half + 1));
    for (int k = -half; k <= half; ++k) {
        const double t = static_cast<double>(k) / points_per_unit;  // output samples
        const double arg = 2 * cutoff * t;
        const double sinc = k == 0 ? 1.0 : std::sin(kPi * arg) / (kPi * arg);
        // NOLINTNEXTLINE(bugprone-misplaced-widening-cast): k + half is in [0, 2 half]
        h[static_cast<size_t>(k + half)] =
            2 * cutoff * sinc * kaiser_window(static_cast<double>(k) / half, beta);
    }
    h = minimum_phase(h, fft_size, kFloorDb);
    double energy = 0;
    for (double v : h) energy += v * v;
    size_t end = h.size();
    for (double tail = 0; end > 1 && tail + h[end - 1] * h[end - 1] < tail_energy * energy;)
        tail += h[end - 1] * h[end - 1], --end;
    h.resize(end);
    const double sum = std::accumulate(h.begin(), h.end(), 0.0);
    double moment = 0, energy_kept = 0;
    for (size_t k = 0; k < h.size(); ++k) {
        h[k] *= points_per_unit / sum;
        moment += static_cast<double>(k) * h[k] * h[k];
        energy_kept += h[k] * h[k];
    }
    return {h, points_per_unit, moment / energy_kept / points_per_unit};
}

}  // namespace

ResamplerKernel design_resampler_kernel(Resampler::Band band) {
    if (band == Resampler::Band::listening)
        return design_kernel(Resampler::kListeningPassEdge, Resampler::kListeningStopEdge,
                             Resampler::kListeningStopBandDb, kListeningPointsPerOutput,
                             kListeningFftSize, kListeningTailEnergy);
    return design_kernel(Resampler::kPassEdge, Resampler::kStopEdge, Resampler::kStopBandDb,
                         kPointsPerOutput, kFftSize, kTailEnergy);
}

}  // namespace tactus
