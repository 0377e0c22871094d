// Flutter (NPI component): its energy is at the flutter rate, and at mix 1 nothing lies above
// NPI's upper edge (40 Hz) at 4 kHz, 8 kHz and 48 kHz; silent frames give exact zeros, also
// after a flutter has faded; a rise from silence starts at phase 0; level steps glide (4 ms
// one-pole) instead of clicking; a rate change is continuous.
#include "tactus/synthesis/flutter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/signals.hpp"
#include "tactus/core/units.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {

constexpr double kNpiHighHz = perception::info(perception::Channel::NPI).range_high_hz;

ControlFrame flutter_frame(double rate_hz, double amplitude, double mix = 0.0) {
    ControlFrame f;
    f.flutter_hz = rate_hz;
    f.flutter_amplitude = amplitude;
    f.square_mix = mix;
    return f;
}

std::vector<float> render(Flutter& flutter, size_t count) {
    std::vector<float> out(count, 1.0f);
    flutter.process(out.data(), static_cast<int>(out.size()));
    return out;
}

TEST(Flutter, EnergyAtTheRateAndNothingAboveNpi) {
    for (double fs : {4000.0, 8000.0, 48000.0}) {
        for (double rate_hz : {3.0, 9.5, 25.0}) {
            Flutter flutter;
            flutter.prepare({.sample_rate_hz = fs});
            flutter.apply(flutter_frame(rate_hz, 0.5, 1.0));
            std::vector<float> out = render(flutter, static_cast<size_t>(fs));  // settle
            out = render(flutter, 1 << 17);
            const std::vector<double> x(out.begin(), out.end());
            const test::Spectrum spectrum(x, fs);
            const double fundamental = spectrum.amplitude_near(rate_hz);
            // A square's fundamental is 4/pi of its level, 0.5 x 4/pi here.
            EXPECT_NEAR(fundamental, 0.5 * 4.0 / kPi, 0.02) << rate_hz << " Hz at " << fs;
            EXPECT_LT(spectrum.max_bin_amplitude(kNpiHighHz + 2.0, fs / 2), 1e-4 * fundamental)
                << rate_hz << " Hz at " << fs << ": harmonics above NPI's band";
            if (3 * rate_hz < kNpiHighHz - 2 * rate_hz) {  // a third harmonic fully inside NPI
                EXPECT_NEAR(spectrum.amplitude_near(3 * rate_hz), fundamental / 3, 0.01);
            }
        }
    }
}

TEST(Flutter, SilentFramesGiveExactZeros) {
    Flutter flutter;
    flutter.prepare({.sample_rate_hz = 48000});
    flutter.apply(flutter_frame(20, 0.0));
    for (float v : render(flutter, 48000)) ASSERT_EQ(v, 0.0f);
    flutter.apply(flutter_frame(20, 0.3));
    EXPECT_GT(test::peak(render(flutter, 4800)), 0.2);
    flutter.apply(flutter_frame(20, 0.0));
    const std::vector<float> out = render(flutter, 48000);
    for (size_t i = 4800; i < out.size(); ++i) ASSERT_EQ(out[i], 0.0f) << i;
    flutter.reset();
    for (float v : render(flutter, 480)) ASSERT_EQ(v, 0.0f);
}

TEST(Flutter, RiseFromSilenceStartsAtPhaseZeroAndGlides) {
    const double fs = 48000, rate_hz = 10, a = 0.4;
    Flutter flutter;
    flutter.prepare({.sample_rate_hz = fs});
    flutter.apply(flutter_frame(rate_hz, a));
    const std::vector<float> out = render(flutter, static_cast<size_t>(fs / 2));
    const double tau_s = 1.0 / (2.0 * kPi * kNpiHighHz);
    const double g = std::exp(-1.0 / (tau_s * fs));
    double glide = 1.0;
    for (size_t i = 0; i < out.size(); ++i) {
        ASSERT_NEAR(out[i], a * (1.0 - glide) * std::sin(2 * kPi * rate_hz * i / fs), 1e-5) << i;
        glide *= g;  // sample i holds the level at time i / fs, then the glide steps
    }
}

TEST(Flutter, LevelStepsAndRateChangesDoNotClick) {
    const double fs = 48000;
    Flutter flutter;
    flutter.prepare({.sample_rate_hz = fs});
    flutter.apply(flutter_frame(30, 0.1));
    std::vector<float> out = render(flutter, 12000);
    // A step from 0.1 to 0.8 at the crest of the wave, then a rate jump: the largest
    // sample-to-sample change stays that of a 30 Hz sine at 0.8 plus the 4 ms glide.
    flutter.apply(flutter_frame(40, 0.8));
    const std::vector<float> after = render(flutter, 12000);
    out.insert(out.end(), after.begin(), after.end());
    double largest = 0;
    for (size_t i = 1; i < out.size(); ++i)
        largest = std::max(largest, double(std::abs(out[i] - out[i - 1])));
    const double sine_step = 0.8 * 2 * kPi * 40 / fs;
    const double glide_step = 0.7 * (1.0 - std::exp(-1.0 / (fs / (2 * kPi * kNpiHighHz))));
    EXPECT_LT(largest, sine_step + glide_step + 1e-6);
}

}  // namespace
}  // namespace tactus
