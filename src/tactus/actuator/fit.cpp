#include "tactus/actuator/fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "tactus/actuator/compensation.hpp"
#include "tactus/core/units.hpp"
#include "tactus/mapping/feature_mapping.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {

// A square wave's lowest harmonic above its fundamental.
constexpr double kSquareHarmonic = 3.0;

// Fits the frequency mapping into [band_low_hz, band_high_hz] (kEdgeMargin inside it) when it
// reaches outside; returns what it did, or "".
std::string fit_frequency(Settings& s, double band_low_hz, double band_high_hz) {
    const double in_min = s[P::frequency_in_min], in_max = s[P::frequency_in_max];
    const double out_min = s[P::frequency_out_min], out_max = s[P::frequency_out_max];
    const double lo = std::min(out_min, out_max), hi = std::max(out_min, out_max);
    if (lo >= band_low_hz && hi <= band_high_hz) return {};
    const double low_hz = band_low_hz * kEdgeMargin, high_hz = band_high_hz / kEdgeMargin;
    const std::string was = fmt::format("mapping.frequency {:g}-{:g} Hz", out_min, out_max);
    if (hi / lo < 1 + 1e-9) {  // one frequency: the nearest the band has
        const double f = std::clamp(lo, low_hz, high_hz);
        s.set(P::frequency_out_min, f);
        s.set(P::frequency_out_max, f);
        return fmt::format("{} -> {:.3g} Hz", was, f);
    }
    FeatureMapping mapping;  // its curve only: the frame rate (smoothing) plays no part
    mapping.configure(s, P::frequency_source, /*frames_per_second=*/1.0);
    const bool log_curve =
        static_cast<int>(s[P::frequency_curve]) == static_cast<int>(MappingCurve::log);
    const double centre_hz = std::sqrt(low_hz * high_hz);
    const double half_span = std::pow(std::sqrt(high_hz / low_hz), kFrequencySpread);
    double window_lo = std::max(lo, centre_hz / half_span);
    double window_hi = std::min(hi, centre_hz * half_span);
    if (!(window_hi / window_lo > 1 + 1e-6)) window_lo = lo, window_hi = hi;  // all outside
    const bool rising = out_max > out_min;
    // A log curve over a non-positive input has no ratios to keep: its inputs stay.
    const bool keep_in = log_curve && !(in_min > 0 && in_max > 0);
    s.set(P::frequency_in_min,
          keep_in ? in_min : mapping.input_for(rising ? window_lo : window_hi));
    s.set(P::frequency_in_max,
          keep_in ? in_max : mapping.input_for(rising ? window_hi : window_lo));
    s.set(P::frequency_out_min, rising ? low_hz : high_hz);
    s.set(P::frequency_out_max, rising ? high_hz : low_hz);
    return fmt::format("{} -> {:.4g}-{:.4g} Hz (in {:.4g}-{:.4g} -> {:.4g}-{:.4g}, log-scaled)",
                       was, s[P::frequency_out_min], s[P::frequency_out_max], in_min, in_max,
                       s[P::frequency_in_min], s[P::frequency_in_max]);
}

double clamp_to_spec(P id, double value) {
    return std::clamp(value, spec(id).min, spec(id).max);
}

}  // namespace

ActuatorFit fit_to_actuator(const ActuatorProfile& a, const Settings& settings) {
    ActuatorFit fit{.settings = settings, .note = {}};
    Settings& s = fit.settings;
    std::vector<std::string> done;
    const bool erm = a.type == ActuatorType::erm;
    const double low_hz = erm ? a.erm_min_drive_hz : a.band_low_hz;
    const double high_hz = erm ? a.erm_max_drive_hz : a.band_high_hz;

    if (erm)
        done.push_back(fmt::format(
            "driven by its intensity (spin-up and braking for its {:g} ms rise), its vibration "
            "{:g}-{:g} Hz following the drive",
            a.rise_ms, a.erm_min_drive_hz, a.erm_max_drive_hz));
    if (std::string f = fit_frequency(s, low_hz, high_hz); !f.empty()) done.push_back(f);

    const double lowest_hz = std::min(s[P::frequency_out_min], s[P::frequency_out_max]);
    const bool square = std::max(s[P::square_mix_out_min], s[P::square_mix_out_max]) > 0;
    if (square && (erm || kSquareHarmonic * lowest_hz > high_hz)) {
        s.set(P::square_mix_out_min, 0);
        s.set(P::square_mix_out_max, 0);
        done.push_back(fmt::format("square harmonics dropped ({:g}x {:g} Hz is above the band)",
                                   kSquareHarmonic, lowest_hz));
    }

    if (a.type == ActuatorType::lra && s[P::frequency_hold] == 0.0) {
        s.set(P::frequency_hold, 1.0);
        done.push_back(
            "mapping.frequency.hold on (its resonance turns a wandering pitch into level)");
    }

    // An ERM's carrier only carries its intensity (post/erm_drive.hpp): its band stays.
    const double band_low = s[P::post_band_low_hz], band_high = s[P::post_band_high_hz];
    const double fitted_low =
        erm ? band_low
            : clamp_to_spec(P::post_band_low_hz, std::max(band_low, a.dc ? 0.0 : low_hz));
    const double fitted_high =
        erm ? band_high : clamp_to_spec(P::post_band_high_hz, std::min(band_high, high_hz));
    if (fitted_low != band_low || fitted_high != band_high) {
        s.set(P::post_band_low_hz, fitted_low);
        s.set(P::post_band_high_hz, fitted_high);
        done.push_back(fmt::format("post.band {:g}-{:g} Hz -> {:.4g}-{:.4g} Hz", band_low,
                                   band_high, fitted_low, fitted_high));
    }

    const double flutter_hz = std::max(s[P::flutter_rate_out_min], s[P::flutter_rate_out_max]);
    if (s[P::flutter_weight] > 0 &&
        (erm || a.response_db(flutter_hz) < -ActuatorCompensation::kBoundDb)) {
        s.set(P::flutter_weight, 0);
        done.push_back(
            erm ? std::string("NPI flutter dropped (slower spin-up than a flutter period)")
                : fmt::format("NPI flutter dropped ({:.0f} dB at {:g} Hz)",
                              a.response_db(flutter_hz), flutter_hz));
    }
    if (s[P::pressure_weight] > 0 && !a.dc) {
        s.set(P::pressure_weight, 0);
        done.push_back("NPIII pressure dropped (dc = false: no sustained offset)");
    } else if (!a.dc && fitted_low < perception::info(perception::Channel::NPIII).range_high_hz) {
        done.push_back(
            fmt::format("post.band_low_hz {:g} Hz passes NPIII pressure the actuator "
                        "cannot hold (dc = false)",
                        fitted_low));
    }

    if (s[P::post_ceiling_db] > gain_to_db(a.max_drive))
        done.push_back(
            fmt::format("output ceiling at its max drive {:.1f} dBFS", gain_to_db(a.max_drive)));
    if (done.empty()) return fit;
    std::string note = fmt::format("{}: fitted to its usable band {:g}-{:g} Hz: ", a.name,
                                   a.band_low_hz, a.band_high_hz);
    for (size_t k = 0; k < done.size(); ++k) note += (k ? "; " : "") + done[k];
    fit.note = std::move(note);
    return fit;
}

}  // namespace tactus
