#include "tactus/actuator/calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "tactus/core/units.hpp"
#include "tactus/dsp/real_fft.hpp"

namespace tactus {
namespace {

constexpr double kPreWindowS = 0.01;  // kept before the impulse response's peak
constexpr double kPostWindowS = 0.5;  // and after it: a Q 20 resonance at 20 Hz has decayed
constexpr double kSmoothingOctaves = 1.0 / 48;
constexpr double kEdgeOctaves = 1.0 / 3;  // left out at each end of the sweep
constexpr double kRegularisation = 1e-6;  // of the sweep's largest power, outside its band

}  // namespace

std::vector<float> exponential_sweep(const SweepSpec& s) {
    if (!(s.low_hz > 0 && s.low_hz < s.high_hz && s.high_hz < s.sample_rate_hz / 2))
        throw std::invalid_argument(fmt::format("sweep {}-{} Hz: the band must lie inside 0-{} Hz",
                                                s.low_hz, s.high_hz, s.sample_rate_hz / 2));
    if (!(s.level > 0 && s.level <= 1))
        throw std::invalid_argument(
            fmt::format("sweep level {}: allowed above 0 up to 1", s.level));
    if (!(s.seconds >= 0.5 && s.seconds <= 120))
        throw std::invalid_argument(fmt::format("sweep of {} s: allowed 0.5 to 120 s", s.seconds));
    const auto n = static_cast<size_t>(s.seconds * s.sample_rate_hz);
    const double rate_l = s.seconds / std::log(s.high_hz / s.low_hz);
    const auto fade = static_cast<size_t>(SweepSpec::kFadeS * s.sample_rate_hz);
    std::vector<float> x(n);
    for (size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) / s.sample_rate_hz;
        double g = s.level;
        if (i < fade) g *= 0.5 - 0.5 * std::cos(M_PI * static_cast<double>(i) / fade);
        if (n - 1 - i < fade)
            g *= 0.5 - 0.5 * std::cos(M_PI * static_cast<double>(n - 1 - i) / fade);
        x[i] = static_cast<float>(
            g * std::sin(2 * M_PI * s.low_hz * rate_l * (std::exp(t / rate_l) - 1)));
    }
    return x;
}

std::vector<std::pair<double, double>> measure_response(std::span<const float> sweep,
                                                        std::span<const float> recorded,
                                                        const SweepSpec& s, int points_per_octave) {
    // Deconvolution: H = Y X* / (|X|^2 + e); the linear impulse response at the delay, the
    // distortion products before it (wrapped to the end of the circular result).
    const int size = next_power_of_two(static_cast<int64_t>(sweep.size() + recorded.size()));
    RealFft fft;
    fft.prepare(size);
    std::fill(fft.time(), fft.time() + size, 0.0f);
    std::copy(sweep.begin(), sweep.end(), fft.time());
    fft.forward();
    std::vector<std::complex<float>> x(fft.spectrum(), fft.spectrum() + fft.bins());
    std::fill(fft.time(), fft.time() + size, 0.0f);
    std::copy(recorded.begin(), recorded.end(), fft.time());
    fft.forward();
    double largest = 0;
    for (const auto& v : x) largest = std::max(largest, static_cast<double>(std::norm(v)));
    for (int k = 0; k < fft.bins(); ++k) {
        const std::complex<double> xk = x[static_cast<size_t>(k)];
        const std::complex<double> yk = fft.spectrum()[k];
        fft.spectrum()[k] = static_cast<std::complex<float>>(
            yk * std::conj(xk) / (std::norm(xk) + kRegularisation * largest));
    }
    fft.inverse();
    std::vector<double> h(fft.time(), fft.time() + size);
    const auto peak = static_cast<size_t>(
        std::max_element(h.begin(), h.end(),
                         [](double a, double b) { return std::abs(a) < std::abs(b); }) -
        h.begin());
    if (!(std::abs(h[peak]) > 0)) throw std::runtime_error("calibrate: the recording is silent");

    // The linear response: from kPreWindowS before the peak, kPostWindowS after, the end faded.
    const auto pre = static_cast<size_t>(kPreWindowS * s.sample_rate_hz);
    const auto post = static_cast<size_t>(kPostWindowS * s.sample_rate_hz);
    const int window_size = next_power_of_two(static_cast<int64_t>(4 * (pre + post)));
    RealFft response;
    response.prepare(window_size);
    std::fill(response.time(), response.time() + window_size, 0.0f);
    for (size_t i = 0; i < pre + post; ++i) {
        const size_t at = (peak + static_cast<size_t>(size) - pre + i) % static_cast<size_t>(size);
        double g = 1;
        if (i > pre + post / 2)
            // NOLINTNEXTLINE(bugprone-integer-division): whole samples, as in the test above
            g = 0.5 + 0.5 * std::cos(M_PI * static_cast<double>(i - pre - post / 2) / (post / 2.0));
        response.time()[i] = static_cast<float>(g * h[at]);
    }
    response.forward();
    const double bin_hz = s.sample_rate_hz / window_size;
    const double from_hz = s.low_hz * std::exp2(kEdgeOctaves),
                 to_hz = s.high_hz / std::exp2(kEdgeOctaves);
    std::vector<std::pair<double, double>> points;
    const int count =
        static_cast<int>(std::floor(std::log2(to_hz / from_hz) * points_per_octave)) + 1;
    for (int i = 0; i < count; ++i) {
        const double f = from_hz * std::exp2(static_cast<double>(i) / points_per_octave);
        const int lo = std::max(
            1, static_cast<int>(std::floor(f * std::exp2(-kSmoothingOctaves / 2) / bin_hz)));
        const int hi = std::min(
            response.bins() - 1,
            std::max(lo,
                     static_cast<int>(std::ceil(f * std::exp2(kSmoothingOctaves / 2) / bin_hz))));
        double power = 0;
        for (int k = lo; k <= hi; ++k)
            power += std::norm(std::complex<double>(response.spectrum()[k]));
        power /= (hi - lo + 1);
        points.emplace_back(f, 10 * std::log10(std::max(power, 1e-30)));
    }
    return points;
}

ActuatorProfile measured_profile(const std::vector<std::pair<double, double>>& measured,
                                 const ActuatorProfile* base) {
    if (measured.size() < 2) throw std::invalid_argument("calibrate: too few measured points");
    ActuatorProfile p;
    if (base) {
        p = *base;
    } else {
        p.type = ActuatorType::voice_coil;
        p.reference_hz =
            std::max_element(measured.begin(), measured.end(), [](const auto& a, const auto& b) {
                return a.second < b.second;
            })->first;
    }
    const double reference_db = interpolate_db(measured, p.reference_hz);
    p.points.clear();
    for (const auto& [f, db] : measured)
        p.points.emplace_back(f, std::clamp(db - reference_db, -100.0, 100.0));
    p.resonance = ResonanceKind::none;
    p.resonance_hz = 0;
    p.q = 1;
    p.rolloff_db_per_octave = 0;
    if (!base) {  // the band: around the peak, within kBandDb of it
        const auto top =
            std::max_element(p.points.begin(), p.points.end(),
                             [](const auto& a, const auto& b) { return a.second < b.second; });
        auto low = top, high = top;
        while (low != p.points.begin() && (low - 1)->second >= top->second - kBandDb) --low;
        while (high + 1 != p.points.end() && (high + 1)->second >= top->second - kBandDb) ++high;
        p.band_low_hz = low->first;
        p.band_high_hz = high->first > low->first ? high->first : low->first * 1.01;
    }
    return p;
}

}  // namespace tactus
