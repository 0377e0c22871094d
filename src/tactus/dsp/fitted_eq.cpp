#include "tactus/dsp/fitted_eq.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "tactus/dsp/biquad_cascade.hpp"
#include "tactus/dsp/design_memo.hpp"

namespace tactus {
namespace {

constexpr double kSectionQ = 1.41;  // one-octave bandwidth at half-octave spacing: smooth sums
constexpr int kIterations = 8;

// Solves the n x n system a x = b in place (Gaussian elimination, partial pivoting).
std::vector<double> solve(std::vector<double> a, std::vector<double> b, int n) {
    for (int c = 0; c < n; ++c) {
        int pivot = c;
        for (int r = c + 1; r < n; ++r)
            if (std::abs(a[r * n + c]) > std::abs(a[pivot * n + c])) pivot = r;
        for (int k = 0; k < n; ++k) std::swap(a[c * n + k], a[pivot * n + k]);
        std::swap(b[c], b[pivot]);
        for (int r = c + 1; r < n; ++r) {
            const double f = a[r * n + c] / a[c * n + c];
            for (int k = c; k < n; ++k) a[r * n + k] -= f * a[c * n + k];
            b[r] -= f * b[c];
        }
    }
    std::vector<double> x(static_cast<size_t>(n));
    for (int r = n - 1; r >= 0; --r) {
        double s = b[r];
        for (int k = r + 1; k < n; ++k) s -= a[r * n + k] * x[k];
        x[r] = s / a[r * n + r];
    }
    return x;
}

// A fit's exact inputs: the rate, the band and the target on its grid.
struct FitKey {
    double sample_rate_hz, low_hz, high_hz;
    std::vector<double> target;  // dB
    bool operator==(const FitKey&) const = default;
};

}  // namespace

std::vector<double> FittedEq::grid(const FitBand& band) {
    const double low_hz = band.low_hz, high_hz = band.high_hz;
    std::vector<double> frequencies(kGridPoints);
    for (int i = 0; i < kGridPoints; ++i)
        frequencies[i] = low_hz * std::pow(high_hz / low_hz, i / (kGridPoints - 1.0));
    return frequencies;
}

FittedEq::Design FittedEq::fit(double sample_rate_hz, const FitBand& band,
                               const std::function<double(double)>& target_db) {
    const double low_hz = band.low_hz;
    const double high_hz = highest_fitted_hz(band.high_hz, sample_rate_hz);
    const std::vector<double> frequencies = grid({.low_hz = low_hz, .high_hz = high_hz});
    FitKey key{sample_rate_hz, low_hz, high_hz, std::vector<double>(kGridPoints)};
    for (int i = 0; i < kGridPoints; ++i) key.target[i] = target_db(frequencies[i]);
    static DesignMemo<FitKey, Design> fits;
    return fits.get(key, [&] {
        return fit_on_grid(sample_rate_hz, {.low_hz = low_hz, .high_hz = high_hz}, frequencies,
                           key.target);
    });
}

// Gauss-Newton on the band's grid `frequencies` towards `target` (dB there).
FittedEq::Design FittedEq::fit_on_grid(double sample_rate_hz, const FitBand& band,
                                       const std::vector<double>& frequencies,
                                       const std::vector<double>& target) {
    const double low_hz = band.low_hz, high_hz = band.high_hz;

    // Half-octave centres across the band.
    std::vector<double> centres;
    for (double f = low_hz; f <= high_hz * 1.001 && centres.size() < kMaxSections;
         f *= std::sqrt(2.0))
        centres.push_back(f);
    const int sections = static_cast<int>(centres.size());
    const int unknowns = sections + 1;  // section gains and an overall gain, dB

    std::vector<double> gains_db(static_cast<size_t>(unknowns), 0.0);
    // Each section's response in dB on the grid, at its gain and at its gain plus the probe: a
    // probe moves one gain, so the others' terms are those of the current response. The sums
    // below add the same terms in the same order as summing every section anew would.
    constexpr double kProbeDb = 0.01, kDamping = 1e-4;
    std::vector<double> term(static_cast<size_t>(sections * kGridPoints));
    std::vector<double> probed(term.size());
    auto section_db = [&](int s, double gain_db, std::vector<double>& into) {
        const BiquadCoefficients c =
            BiquadCoefficients::peaking(centres[s], kSectionQ, gain_db, sample_rate_hz);
        for (int i = 0; i < kGridPoints; ++i)
            into[s * kGridPoints + i] = c.magnitude_db(frequencies[i], sample_rate_hz);
    };
    // The response at grid point i with gain u probed (u < 0: none).
    auto response_db = [&](int i, int u) {
        double db = u == sections ? gains_db[sections] + kProbeDb : gains_db[sections];
        for (int s = 0; s < sections; ++s) db += (s == u ? probed : term)[s * kGridPoints + i];
        return db;
    };
    for (int iteration = 0; iteration < kIterations; ++iteration) {
        for (int s = 0; s < sections; ++s) {
            section_db(s, gains_db[s], term);
            section_db(s, gains_db[s] + kProbeDb, probed);
        }
        std::vector<double> jacobian(static_cast<size_t>(kGridPoints * unknowns));
        std::vector<double> error(kGridPoints);
        for (int i = 0; i < kGridPoints; ++i) {
            const double now = response_db(i, -1);
            error[i] = target[i] - now;
            for (int u = 0; u < unknowns; ++u)
                jacobian[i * unknowns + u] = (response_db(i, u) - now) / kProbeDb;
        }
        std::vector<double> normal(static_cast<size_t>(unknowns * unknowns), 0.0);
        std::vector<double> rhs(static_cast<size_t>(unknowns), 0.0);
        for (int i = 0; i < kGridPoints; ++i)
            for (int u = 0; u < unknowns; ++u) {
                rhs[u] += jacobian[i * unknowns + u] * error[i];
                for (int v = 0; v < unknowns; ++v)
                    normal[u * unknowns + v] +=
                        jacobian[i * unknowns + u] * jacobian[i * unknowns + v];
            }
        for (int u = 0; u < unknowns; ++u) normal[u * unknowns + u] += kDamping;
        const std::vector<double> step = solve(normal, rhs, unknowns);
        for (int u = 0; u < unknowns; ++u) gains_db[u] += step[u];
    }
    Design fitted;
    fitted.count = sections;
    for (int s = 0; s < sections; ++s)
        fitted.sections[s] =
            BiquadCoefficients::peaking(centres[s], kSectionQ, gains_db[s], sample_rate_hz);
    fitted.gain = db_to_gain(gains_db[sections]);
    return fitted;
}

void FittedEq::set(const Design& design) noexcept {
    count_ = design.count;
    for (int s = 0; s < count_; ++s) sections_[s].set(design.sections[s]);
    gain_ = design.gain;
    to_ = design;
    glide_steps_ = glide_done_ = 0;
}

void FittedEq::glide_to(const Design& design, int samples) noexcept {
    from_.count = count_;
    for (int s = 0; s < count_; ++s) from_.sections[s] = sections_[s].coefficients();
    from_.gain = gain_;
    to_ = design;
    glide_steps_ = std::max(1, samples / kGlideStep);
    glide_done_ = 0;
    until_step_ = 0;
    if (samples <= 0) set(design);
}

void FittedEq::step_glide() noexcept {
    ++glide_done_;
    const double t = static_cast<double>(glide_done_) / glide_steps_;
    if (glide_done_ >= glide_steps_) return set(to_);
    const auto mix = [t](double a, double b) { return a + t * (b - a); };
    for (int s = 0; s < count_; ++s) {
        const BiquadCoefficients& a = from_.sections[s];
        const BiquadCoefficients& b = to_.sections[s];
        sections_[s].set(
            {mix(a.b0, b.b0), mix(a.b1, b.b1), mix(a.b2, b.b2), mix(a.a1, b.a1), mix(a.a2, b.a2)});
    }
    gain_ = mix(from_.gain, to_.gain);
}

void FittedEq::reset() noexcept {
    for (auto& s : sections_) s.reset();
}

void FittedEq::process(float* samples, int count) noexcept {
    while (glide_done_ < glide_steps_ && count > 0) {  // a glide: steps between short runs
        if (until_step_ == 0) {
            step_glide();
            until_step_ = kGlideStep;
        }
        const int run = std::min(count, until_step_);
        process_cascade(sections_.data(), count_, samples, run, gain_);
        samples += run;
        count -= run;
        until_step_ -= run;
    }
    process_cascade(sections_.data(), count_, samples, count, gain_);
}

double FittedEq::magnitude_db(double frequency_hz) const {
    double db = gain_to_db(gain_);
    for (int s = 0; s < count_; ++s)
        db += sections_[s].coefficients().magnitude_db(frequency_hz, sample_rate_hz_);
    return db;
}

}  // namespace tactus
