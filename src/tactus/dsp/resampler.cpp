#include "tactus/dsp/resampler.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

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
constexpr int kLanes = 8;             // taps padded to a multiple: the dot product vectorises

// The minimum-phase kernel, kPointsPerOutput points per sample of the lower rate (the output's,
// reducing it), unit sum over the points divided by kPointsPerOutput (unit DC gain in
// continuous time). Rate-independent: made once per band.
struct Kernel {
    std::vector<double> points;
    int points_per_unit = kPointsPerOutput;
    double delay_output_samples = 0;
};

Kernel design_kernel(double pass_edge, double stop_edge, double stop_band_db,
                     int points_per_unit = kPointsPerOutput, int fft_size = kFftSize,
                     double tail_energy = kTailEnergy) {
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

const Kernel& kernel(Resampler::Band band) {  // thread-safe initialisation, each when first used
    if (band == Resampler::Band::listening) {
        static const Kernel listening =
            design_kernel(Resampler::kListeningPassEdge, Resampler::kListeningStopEdge,
                          Resampler::kListeningStopBandDb, kListeningPointsPerOutput,
                          kListeningFftSize, kListeningTailEnergy);
        return listening;
    }
    static const Kernel analysis =
        design_kernel(Resampler::kPassEdge, Resampler::kStopEdge, Resampler::kStopBandDb);
    return analysis;
}

// The kernel at `t` samples (of the lower rate) after its start (0 outside it), linearly
// interpolated.
double kernel_at(const Kernel& k, double t) {
    const double x = t * k.points_per_unit;
    if (x < 0) return 0;
    const auto i = static_cast<size_t>(x);
    if (i + 1 >= k.points.size()) return 0;
    const double f = x - static_cast<double>(i);
    return k.points[i] + f * (k.points[i + 1] - k.points[i]);
}

bool whole(double x) {
    return x == std::floor(x) && x < 1e12;
}

}  // namespace

Resampler::Ratio Resampler::ratio_for(double input_rate_hz, double output_rate_hz) {
    Ratio r{kMaxPhases + 1, 1};
    if (whole(input_rate_hz) && whole(output_rate_hz)) {
        const auto in = static_cast<int64_t>(input_rate_hz);
        const auto out = static_cast<int64_t>(output_rate_hz);
        const int64_t g = std::gcd(in, out);
        r = {out / g, in / g};
    }
    if (r.up > kMaxPhases) {  // the nearest ratio with L = kMaxPhases
        r.up = kMaxPhases;
        r.down = std::max<int64_t>(1, std::llround(input_rate_hz / output_rate_hz * kMaxPhases));
        const int64_t g = std::gcd(r.up, r.down);
        r.up /= g;
        r.down /= g;
    }
    return r;
}

void Resampler::prepare(double input_rate_hz, double output_rate_hz, int max_block, Band band) {
    if (!(output_rate_hz > 0 && (output_rate_hz <= input_rate_hz || band == Band::listening)))
        throw std::invalid_argument("resampler: the output rate must be in (0, input rate]");
    const Ratio r = ratio_for(input_rate_hz, output_rate_hz);
    up_ = r.up;
    down_ = r.down;
    output_rate_hz_ = input_rate_hz * static_cast<double>(up_) / static_cast<double>(down_);
    const Kernel& k = kernel(band);
    // Input samples per output sample: down / up. Tap i reads the input i samples before the
    // newest, at (phase / up + i) input samples = (phase / up + i) up / down output samples;
    // the kernel's unit is a sample of the lower rate: the output's, unless the rate rises.
    const double outputs_per_input = static_cast<double>(up_) / static_cast<double>(down_);
    const double units_per_input = std::min(1.0, outputs_per_input);
    delay_output_samples_ = k.delay_output_samples * outputs_per_input / units_per_input;
    const double span = static_cast<double>(k.points.size()) / k.points_per_unit;  // units
    const int needed = static_cast<int>(std::ceil(span / units_per_input)) + 1;
    taps_ = (needed + kLanes - 1) / kLanes * kLanes;
    kernel_.assign(static_cast<size_t>(up_ * taps_), 0.0f);
    for (int64_t p = 0; p < up_; ++p) {
        float* phase = kernel_.data() + p * taps_;
        double sum = 0;
        for (int i = 0; i < taps_; ++i) {
            const double t =
                (static_cast<double>(p) / static_cast<double>(up_) + i) * units_per_input;
            sum += phase[taps_ - 1 - i] = static_cast<float>(kernel_at(k, t) * units_per_input);
        }
        for (int i = 0; i < taps_; ++i) phase[i] = static_cast<float>(phase[i] / sum);  // DC: 1
    }
    history_.assign(static_cast<size_t>(taps_ - 1 + max_block), 0.0f);
    reset();
}

void Resampler::reset() noexcept {
    std::fill(history_.begin(), history_.end(), 0.0f);
    next_output_ = next_base_ = phase_ = written_ = 0;
}

int Resampler::process(const float* in, int count, float* out) noexcept {
    const int taps = taps_;
    float* const history = history_.data();
    std::copy_n(in, count, history + taps - 1);
    const int64_t end = written_ + count;
    int produced = 0;
    while (next_base_ < end) {
        const float* x = history + (next_base_ - written_);  // taps samples, newest last
        const float* w = kernel_.data() + phase_ * taps;
        float s[kLanes] = {};
        for (int i = 0; i < taps; i += kLanes)
            for (int j = 0; j < kLanes; ++j) s[j] += w[i + j] * x[i + j];
        out[produced++] = ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
        phase_ += down_;
        next_base_ += phase_ / up_;
        phase_ %= up_;
        ++next_output_;
    }
    std::copy(history + count, history + count + taps - 1, history);
    written_ = end;
    return produced;
}

}  // namespace tactus
