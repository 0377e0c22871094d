// The actuator model: a linear profile's steady-state response to sines follows its response_db
// (closed form, profile.cpp) within 1 dB across and around the band; an ERM spins up with its
// rise_ms (10-90 %), vibrates at the speed-tied frequency with an amplitude that follows the
// drive, and only buzzes under a bipolar carrier (it averages out).
#include "tactus/actuator/actuator_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "support/signals.hpp"
#include "tactus/io/actuator_file.hpp"

namespace tactus {
namespace {

double model_gain_db(const ActuatorProfile& a, double f, double fs) {
    ActuatorModel m;
    m.prepare({.sample_rate_hz = fs}, a);
    return test::measured_gain_db([&](float* x, int n) { m.process(x, x, n); }, f, fs);
}

TEST(ActuatorModel, LinearResponseFollowsTheProfile) {
    for (const char* name : {"lra-175", "voice-coil"}) {
        const ActuatorProfile a = load_actuator(resolve_actuator(name));
        for (double fs : {44100.0, 48000.0}) {
            const double low = a.band_low_hz / 2, high = std::min(a.band_high_hz * 2, 2000.0);
            double worst = 0;
            for (double f = low; f <= high; f *= 1.1) {
                const double error = model_gain_db(a, f, fs) - a.response_db(f);
                worst = std::max(worst, std::abs(error));
                EXPECT_NEAR(error, 0.0, 1.0) << name << " at " << f << " Hz, " << fs << " Hz";
            }
            std::cout << name << " at " << fs << " Hz: worst " << worst << " dB\n";
        }
    }
}

TEST(ActuatorModel, LraPeaksAtItsResonance) {
    const ActuatorProfile a = load_actuator(resolve_actuator("lra-175"));
    EXPECT_NEAR(model_gain_db(a, 175, 48000), 0.0, 0.5);
    EXPECT_LT(model_gain_db(a, 150, 48000), -6.0);  // Q 10: the band's edges are well down
    EXPECT_LT(model_gain_db(a, 40, 48000), -40.0);
    EXPECT_LT(model_gain_db(a, 500, 48000), -25.0);
}

// The ERM's speed after a step of `drive` lasting `seconds`: peak |displacement| over the last
// 20 ms and the frequency from zero crossings over the last 100 ms.
struct Spin {
    double amplitude, frequency_hz;
};
Spin spin(const ActuatorProfile& a, const std::vector<float>& drive, double fs) {
    ActuatorModel m;
    m.prepare({.sample_rate_hz = fs}, a);
    std::vector<float> y(drive.size());
    m.process(drive.data(), y.data(), static_cast<int>(y.size()));
    const auto tail = static_cast<size_t>(0.1 * fs), last = static_cast<size_t>(0.02 * fs);
    int crossings = 0;
    for (size_t i = y.size() - tail; i + 1 < y.size(); ++i)
        crossings += std::signbit(y[i]) != std::signbit(y[i + 1]);
    return {test::peak(std::span<const float>(y).last(last)), crossings / 2.0 / 0.1};
}

TEST(ActuatorModel, ErmFrequencyAndAmplitudeFollowItsDrive) {
    const ActuatorProfile a = load_actuator(resolve_actuator("erm"));
    const double fs = 48000;
    const auto n = static_cast<size_t>(fs);
    const Spin full = spin(a, std::vector<float>(n, 1.0f), fs);
    EXPECT_NEAR(full.amplitude, 1.0, 0.01);
    EXPECT_NEAR(full.frequency_hz, a.erm_max_drive_hz, 5);
    const Spin half = spin(a, std::vector<float>(n, 0.5f), fs);
    EXPECT_NEAR(half.amplitude, 0.5, 0.01);
    EXPECT_NEAR(half.frequency_hz, (a.erm_min_drive_hz + a.erm_max_drive_hz) / 2, 5);
    // A bipolar carrier at full scale averages out: the motor barely turns.
    const Spin buzz = spin(a, test::sine(175, fs, n, 1.0), fs);
    EXPECT_LT(buzz.amplitude, 0.05);
}

TEST(ActuatorModel, ErmRisesInItsRiseTime) {
    const ActuatorProfile a = load_actuator(resolve_actuator("erm"));
    const double fs = 48000;
    ActuatorModel m;
    m.prepare({.sample_rate_hz = fs}, a);
    std::vector<float> y(static_cast<size_t>(fs));
    const std::vector<float> drive(y.size(), 1.0f);
    m.process(drive.data(), y.data(), static_cast<int>(y.size()));
    // The envelope: the running peak over a period of the slowest vibration.
    const auto period = static_cast<size_t>(fs / a.erm_min_drive_hz);
    const auto reached = [&](double level) {
        for (size_t i = period; i < y.size(); ++i)
            if (test::peak(std::span<const float>(y).subspan(i - period, period)) >= level)
                return static_cast<double>(i) / fs * 1e3;
        return static_cast<double>(INFINITY);
    };
    EXPECT_NEAR(reached(0.9) - reached(0.1), a.rise_ms, 0.15 * a.rise_ms);
    std::vector<float> silence(y.size(), 0.0f);
    m.reset();
    m.process(silence.data(), y.data(), static_cast<int>(y.size()));
    EXPECT_EQ(test::peak(y), 0.0);
}

}  // namespace
}  // namespace tactus
