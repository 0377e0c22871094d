// Test signals and measurements shared by the unit tests: a deterministic random generator,
// sines, noise, a drum-like pattern with known onset times, RMS / amplitude fits and a
// double-precision FFT (independent of the library's FFTW wrapper) for spectral checks.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

namespace tactus::test {

constexpr double kTestPi = 3.14159265358979323846;
constexpr double kCornerDb = -3.0102999566;  // 20 log10(1/sqrt(2)): a Butterworth corner

// splitmix64: the same sequence on every platform (std:: distributions are unspecified).
class Random {
  public:
    explicit Random(uint64_t seed) : state_(seed ^ 0x9E3779B97F4A7C15ull) {}
    uint64_t next() {
        uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    double gaussian() {
        const double u = std::max(uniform(), 1e-300), v = uniform();
        return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * kTestPi * v);
    }

  private:
    uint64_t state_;
};

inline std::vector<float> sine(double frequency_hz, double sample_rate_hz, size_t count,
                               double amplitude = 1.0, double phase = 0.0) {
    std::vector<float> x(count);
    for (size_t n = 0; n < count; ++n)
        x[n] = static_cast<float>(amplitude * std::sin(2.0 * kTestPi * frequency_hz *
                                                           static_cast<double>(n) / sample_rate_hz +
                                                       phase));
    return x;
}

// Band-limited sawtooth (additive, harmonics below 0.45 fs), peak about `amplitude`.
inline std::vector<float> sawtooth(double frequency_hz, double sample_rate_hz, size_t count,
                                   double amplitude = 0.5) {
    std::vector<float> x(count);
    const int harmonics = static_cast<int>(0.45 * sample_rate_hz / frequency_hz);
    for (size_t n = 0; n < count; ++n) {
        double s = 0.0;
        const double phase = 2.0 * kTestPi * frequency_hz * static_cast<double>(n) / sample_rate_hz;
        for (int k = 1; k <= harmonics; ++k) s += std::sin(k * phase) / k;
        x[n] = static_cast<float>(amplitude * (2.0 / kTestPi) * s);
    }
    return x;
}

// Uniform white noise in [-amplitude, amplitude).
inline std::vector<float> white_noise(size_t count, uint64_t seed, double amplitude = 1.0) {
    Random random(seed);
    std::vector<float> x(count);
    for (auto& v : x) v = static_cast<float>(amplitude * random.uniform(-1.0, 1.0));
    return x;
}

inline double rms(std::span<const float> x) {
    double sum = 0.0;
    for (float v : x) sum += double(v) * v;
    return x.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(x.size()));
}

inline double peak(std::span<const float> x) {
    double p = 0.0;
    for (float v : x) p = std::max(p, static_cast<double>(std::abs(v)));
    return p;
}

// Steady-state gain in dB of `process` (a callable on float* , int) for a sine at frequency_hz:
// the sine runs for settle_s + whole periods covering at least measure_s, and the RMS of the
// output over the last whole number of periods is compared with the input's over the same span.
template <typename Process>
double measured_gain_db(Process&& process, double frequency_hz, double sample_rate_hz,
                        double settle_s = 1.0, double measure_s = 0.5, double amplitude = 0.25) {
    const double periods = std::ceil(measure_s * frequency_hz);
    const auto measured =
        static_cast<size_t>(std::llround(periods * sample_rate_hz / frequency_hz));
    const auto settle = static_cast<size_t>(settle_s * sample_rate_hz);
    std::vector<float> x = sine(frequency_hz, sample_rate_hz, settle + measured, amplitude);
    const std::vector<float> input = x;
    process(x.data(), static_cast<int>(x.size()));
    const std::span<const float> in_tail(input.data() + settle, measured);
    const std::span<const float> out_tail(x.data() + settle, measured);
    return 20.0 * std::log10(rms(out_tail) / rms(in_tail));
}

// In-place iterative radix-2 FFT (size a power of two), double precision.
inline void fft(std::vector<std::complex<double>>& a) {
    const size_t n = a.size();
    for (size_t i = 1, j = 0; i < n; ++i) {
        size_t bit = n >> 1;
        for (; j & bit; bit >>= 1) j ^= bit;
        j ^= bit;
        if (i < j) std::swap(a[i], a[j]);
    }
    for (size_t length = 2; length <= n; length <<= 1) {
        const std::complex<double> step = std::polar(1.0, -2.0 * kTestPi / double(length));
        for (size_t start = 0; start < n; start += length) {
            std::complex<double> w = 1.0;
            for (size_t k = 0; k < length / 2; ++k) {
                const std::complex<double> u = a[start + k], v = a[start + k + length / 2] * w;
                a[start + k] = u + v;
                a[start + k + length / 2] = u - v;
                w *= step;
            }
        }
    }
}

// One-sided spectrum of a real signal (length a power of two) under a 4-term Blackman-Harris
// window (sidelobes below -92 dB). `power[k]` is |X_k|^2; amplitude_near() turns the power in a
// main lobe back into the amplitude of the sinusoid that caused it, whatever its offset from
// the bin centre.
class Spectrum {
  public:
    Spectrum(std::span<const double> x, double sample_rate_hz)
        : bin_hz_(sample_rate_hz / x.size()) {
        const size_t n = x.size();
        std::vector<std::complex<double>> a(n);
        window_power_ = window_sum_ = 0.0;
        for (size_t i = 0; i < n; ++i) {
            const double t = 2.0 * kTestPi * double(i) / double(n);
            const double w = 0.35875 - 0.48829 * std::cos(t) + 0.14128 * std::cos(2 * t) -
                             0.01168 * std::cos(3 * t);
            window_power_ += w * w;
            window_sum_ += w;
            a[i] = x[i] * w;
        }
        fft(a);
        power_.resize(n / 2 + 1);
        for (size_t k = 0; k <= n / 2; ++k) power_[k] = std::norm(a[k]);
        size_ = n;
    }

    double bin_hz() const { return bin_hz_; }
    size_t bins() const { return power_.size(); }
    double power(size_t k) const { return power_[k]; }
    size_t bin_of(double frequency_hz) const {
        return std::min(bins() - 1, static_cast<size_t>(std::llround(frequency_hz / bin_hz_)));
    }
    // Amplitude of a sinusoid near frequency_hz, from the power within +-lobe bins.
    double amplitude_near(double frequency_hz, int lobe = 6) const {
        const auto centre = static_cast<long>(bin_of(frequency_hz));
        double sum = 0.0;
        for (long k = std::max(1L, centre - lobe);
             k <= std::min(static_cast<long>(bins()) - 1, centre + lobe); ++k)
            sum += power_[static_cast<size_t>(k)];
        return std::sqrt(4.0 * sum / (double(size_) * window_power_));
    }
    // Largest amplitude of a single bin in [from_hz, to_hz], scaled so that a sinusoid on a
    // bin centre of amplitude A reads A (off-centre it reads up to 0.83 dB less).
    double max_bin_amplitude(double from_hz, double to_hz) const {
        double best = 0.0;
        const size_t first = std::max<size_t>(1, static_cast<size_t>(std::ceil(from_hz / bin_hz_)));
        const size_t last = std::min(bins() - 1, static_cast<size_t>(std::floor(to_hz / bin_hz_)));
        for (size_t k = first; k <= last; ++k) best = std::max(best, power_[k]);
        return 2.0 * std::sqrt(best) / window_sum_;
    }

  private:
    double bin_hz_;
    double window_power_ = 0.0, window_sum_ = 0.0;
    size_t size_ = 0;
    std::vector<double> power_;
};

// A drum-like test signal: kicks (pitch-swept decaying sine), snares (noise + tone), hats
// (differentiated noise), on a 16th grid at 120 BPM, with stretches of digital silence and a
// quiet passage. `onsets` holds the sample index of every hit.
struct DrumSignal {
    std::vector<float> audio;
    std::vector<int64_t> onsets;
};

inline DrumSignal drum_pattern(double sample_rate_hz, double seconds, uint64_t seed) {
    Random random(seed);
    DrumSignal d;
    d.audio.assign(static_cast<size_t>(seconds * sample_rate_hz), 0.0f);
    const double step_s = 60.0 / 120.0 / 4.0;
    const auto add_hit = [&](double t, int kind, double gain) {
        const auto start = static_cast<size_t>(std::llround(t * sample_rate_hz));
        if (start >= d.audio.size()) return;
        d.onsets.push_back(static_cast<int64_t>(start));
        const double decay_s = kind == 0 ? 0.18 : kind == 1 ? 0.09 : 0.025;
        const auto length =
            std::min(d.audio.size() - start, static_cast<size_t>(6 * decay_s * sample_rate_hz));
        double phase = 0.0, previous_noise = 0.0;
        for (size_t i = 0; i < length; ++i) {
            const double ts = double(i) / sample_rate_hz;
            const double env = std::exp(-ts / decay_s);
            double v = 0.0;
            if (kind == 0) {  // kick: 120 -> 50 Hz sweep
                phase += 2 * kTestPi * (50.0 + 70.0 * std::exp(-ts / 0.03)) / sample_rate_hz;
                v = std::sin(phase);
            } else if (kind == 1) {  // snare: noise and a 190 Hz tone
                phase += 2 * kTestPi * 190.0 / sample_rate_hz;
                v = 0.6 * random.uniform(-1.0, 1.0) + 0.5 * std::sin(phase);
            } else {  // hat: differentiated noise (bright)
                const double noise = random.uniform(-1.0, 1.0);
                v = 0.5 * (noise - previous_noise);
                previous_noise = noise;
            }
            d.audio[start + i] += static_cast<float>(gain * env * v);
        }
    };
    for (int step = 0;; ++step) {
        const double t = 0.1 + step * step_s;
        if (t >= seconds - 0.2) break;
        const int bar_step = step % 16, bar = step / 16;
        if (bar % 4 == 2 && bar_step >= 8) continue;    // a gap of digital silence
        const double gain = bar % 4 == 3 ? 0.05 : 0.8;  // a quiet bar
        if (bar_step == 0 || bar_step == 10 || (bar_step == 7 && random.uniform() < 0.5))
            add_hit(t, 0, gain);
        if (bar_step == 4 || bar_step == 12) add_hit(t, 1, gain * 0.8);
        if (bar_step % 2 == 0) add_hit(t, 2, gain * 0.4);
    }
    std::sort(d.onsets.begin(), d.onsets.end());
    d.onsets.erase(std::unique(d.onsets.begin(), d.onsets.end()), d.onsets.end());
    // The gaps must stay digital silence: hits ringing into them are cut.
    for (size_t n = 0; n < d.audio.size(); ++n) {
        const double t = double(n) / sample_rate_hz - 0.1;
        const auto step = static_cast<long>(std::floor(t / step_s));
        if (t >= 0 && (step / 16) % 4 == 2 && step % 16 >= 9) d.audio[n] = 0.0f;
    }
    return d;
}

// Whether two signals are the same, bit for bit (NaNs and signed zeros included).
inline bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace tactus::test
