#include "tactus/perception/threshold.hpp"

#include <algorithm>

namespace tactus::perception {
namespace {

// A flat curve with straight skirts (dB per octave) outside [low_hz, high_hz]; low_hz = 0 keeps
// it flat down to a static stimulus.
double flat_band_db(double frequency_hz, double level_db, double low_hz, double low_slope,
                    double high_hz, double high_slope) {
    double db = level_db + std::max(0.0, high_slope * std::log2(frequency_hz / high_hz));
    if (low_hz > 0) db += std::max(0.0, low_slope * std::log2(low_hz / frequency_hz));
    return db;
}

double fraction_between(double value, double low, double high) {  // on a log scale, 0..1
    return std::clamp(std::log(value / low) / std::log(high / low), 0.0, 1.0);
}

// Fraction (0..1) of P's spatial and temporal summation that holds at a frequency: none at
// <= 40 Hz, full at >= 80 Hz, linear in log-frequency between [derived].
double summation_weight(double frequency_hz) {
    return fraction_between(frequency_hz, kNoSummationBelowHz, kFullSummationAboveHz);
}

// Threshold change of P from the reference condition: +3 dB per halving of area down to
// 0.02 cm^2, +3 dB per halving of duration below 1 s (none with the smallest contactors:
// weighted by where the area lies between 0.02 and 2.9 cm^2 [derived]).
double p_area_shift_db(double frequency_hz, double contact_area_cm2) {
    const double area = std::clamp(contact_area_cm2, kSmallestSummingAreaCm2, kReferenceAreaCm2);
    return summation_weight(frequency_hz) * kSummationDbPerDoubling *
           std::log2(kReferenceAreaCm2 / area);
}

double p_duration_shift_db(double frequency_hz, const Stimulus& stimulus) {
    const double duration =
        std::clamp(stimulus.duration_s, kShortestDurationS, kReferenceDurationS);
    const double with_area =
        fraction_between(stimulus.contact_area_cm2, kSmallestSummingAreaCm2, kReferenceAreaCm2);
    return summation_weight(frequency_hz) * with_area * kSummationDbPerDoubling *
           std::log2(kReferenceDurationS / duration);
}

}  // namespace

double threshold_db(Channel channel, double frequency_hz, const Stimulus& stimulus) {
    switch (channel) {
        case Channel::P:
            return p_threshold_db(frequency_hz) +
                   p_area_shift_db(frequency_hz, stimulus.contact_area_cm2) +
                   p_duration_shift_db(frequency_hz, stimulus);
        case Channel::NPI: {
            const double octaves_from_notch =
                std::log2(frequency_hz / kNpiNotchHz) / kNpiNotchWidthOctaves;
            return flat_band_db(frequency_hz, kNpiFlatDb, kNpiLowCornerHz, kNpiLowSlopeDbPerOctave,
                                kNpiHighCornerHz, kNpiHighSlopeDbPerOctave) -
                   kNpiNotchDepthDb * std::exp(-0.5 * octaves_from_notch * octaves_from_notch);
        }
        case Channel::NPII:
            return p_threshold_db(frequency_hz) + kNpiiAbovePDb;
        case Channel::NPIII:
            return flat_band_db(frequency_hz, kNpiiiFlatDb, 0.0, 0.0, kNpiiiHighCornerHz,
                                kNpiiiHighSlopeDbPerOctave);
    }
    return INFINITY;
}

Channel detecting_channel(double frequency_hz, const Stimulus& stimulus) {
    Channel best = Channel::P;
    double best_db = threshold_db(best, frequency_hz, stimulus);
    for (const auto& c : kChannels)
        if (const double db = threshold_db(c.channel, frequency_hz, stimulus); db < best_db)
            best = c.channel, best_db = db;
    return best;
}

double detection_threshold_db(double frequency_hz, const Stimulus& stimulus) {
    return threshold_db(detecting_channel(frequency_hz, stimulus), frequency_hz, stimulus);
}

}  // namespace tactus::perception
