// Resampler against closed forms: unit gain at DC and in the pass band, the stop band (what
// would alias) at least kStopBandDb - 5 dB down, output n at input position n * M / L (the count
// after any input), exact ratios for the usual rates and a bounded one otherwise, and the same
// output for any block split. The listening band converts either way: flat to its pass edge,
// images and aliases kListeningStopBandDb - 10 dB down.
#include "tactus/dsp/resampler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tactus/core/units.hpp"

namespace tactus {
namespace {

std::vector<float> resample(Resampler& r, const std::vector<float>& x, int block) {
    std::vector<float> y(x.size());
    size_t written = 0;
    for (size_t i = 0; i < x.size(); i += static_cast<size_t>(block)) {
        const int count = static_cast<int>(std::min<size_t>(block, x.size() - i));
        written += static_cast<size_t>(r.process(x.data() + i, count, y.data() + written));
    }
    y.resize(written);
    return y;
}

std::vector<float> sine(double hz, double rate_hz, size_t n) {
    std::vector<float> x(n);
    for (size_t i = 0; i < n; ++i)
        x[i] = static_cast<float>(std::sin(2 * kPi * hz * static_cast<double>(i) / rate_hz));
    return x;
}

double rms(const std::vector<float>& y, size_t from) {
    double sum = 0;
    for (size_t i = from; i < y.size(); ++i) sum += static_cast<double>(y[i]) * y[i];
    return std::sqrt(sum / static_cast<double>(y.size() - from));
}

TEST(Resampler, ExactRatiosForTheUsualRatesAndABoundedOneOtherwise) {
    for (const double fs :
         {16000.0, 22050.0, 32000.0, 44100.0, 48000.0, 88200.0, 96000.0, 176400.0, 192000.0}) {
        Resampler r;
        r.prepare(fs, 16000, 512);
        EXPECT_EQ(r.output_rate_hz(), 16000.0) << fs;
        EXPECT_LE(r.up(), Resampler::kMaxPhases) << fs;
    }
    Resampler odd;
    odd.prepare(44099, 16000, 512);
    EXPECT_LE(odd.up(), Resampler::kMaxPhases);
    EXPECT_NEAR(odd.output_rate_hz(), 16000, 16000.0 / (2 * Resampler::kMaxPhases));
    EXPECT_THROW(odd.prepare(8000, 16000, 512), std::invalid_argument);
}

TEST(Resampler, OutputCountFollowsTheInputPosition) {
    Resampler r;
    r.prepare(44100, 16000, 97);
    std::vector<float> x(97, 0.25f), y(97);
    int64_t inputs = 0, outputs = 0;
    for (int call = 0; call < 50; ++call) {
        outputs += r.process(x.data(), 97, y.data());
        inputs += 97;
        // Output n exists once input floor(n * 441 / 160) has been written.
        EXPECT_EQ(r.inputs_for(outputs - 1) <= inputs, true);
        EXPECT_GT(r.inputs_for(outputs), inputs);
        EXPECT_EQ(outputs, r.outputs_written());
    }
}

TEST(Resampler, UnitGainAtDcAndInThePassBand) {
    for (const double fs : {16000.0, 44100.0, 48000.0, 192000.0}) {
        Resampler r;
        r.prepare(fs, 16000, 256);
        const auto dc = resample(r, std::vector<float>(static_cast<size_t>(0.1 * fs), 0.5f), 256);
        EXPECT_NEAR(dc.back(), 0.5, 1e-5) << fs;
        for (const double hz : {100.0, 1000.0, 4000.0, 0.98 * Resampler::kPassEdge * 16000}) {
            r.reset();
            const auto y = resample(r, sine(hz, fs, static_cast<size_t>(0.2 * fs)), 256);
            EXPECT_NEAR(rms(y, 320), std::sqrt(0.5), 0.01 * std::sqrt(0.5))
                << fs << " Hz in, " << hz;
        }
    }
}

TEST(Resampler, WhatWouldAliasIsInTheStopBand) {
    for (const double fs : {44100.0, 48000.0, 96000.0}) {
        Resampler r;
        r.prepare(fs, 16000, 256);
        for (const double hz : {Resampler::kStopEdge * 16000, 9000.0, 12000.0, 15000.0}) {
            r.reset();
            const auto y = resample(r, sine(hz, fs, static_cast<size_t>(0.2 * fs)), 256);
            EXPECT_LT(gain_to_db(rms(y, 320) / std::sqrt(0.5)), -(Resampler::kStopBandDb - 5))
                << fs << " Hz in, " << hz;
        }
    }
}

TEST(Resampler, AStepArrivesAfterTheStatedDelay) {
    // A step at input sample s shows at output position s * L / M: half its height is reached
    // within the kernel's delay (minimum phase: most of the response comes early).
    Resampler r;
    r.prepare(48000, 16000, 480);
    std::vector<float> x(4800, 0.0f);
    std::fill(x.begin() + 2400, x.end(), 1.0f);
    const auto y = resample(r, x, 480);
    const auto half = std::find_if(y.begin(), y.end(), [](float v) { return v >= 0.5f; });
    const double arrival = static_cast<double>(half - y.begin()) - 800.0;  // output samples
    EXPECT_GE(arrival, 0.0);
    EXPECT_LE(arrival, r.delay_output_samples() + 1.0);
    EXPECT_LT(r.delay_output_samples() / 16000.0, 0.001) << "under a millisecond";
}

TEST(Resampler, AnyBlockSplitGivesTheSameOutput) {
    const auto x = sine(997, 44100, 20000);
    Resampler whole;
    whole.prepare(44100, 16000, 4096);
    const auto expected = resample(whole, x, 4096);
    for (const int block : {1, 3, 64, 441}) {
        Resampler r;
        r.prepare(44100, 16000, block);
        EXPECT_EQ(resample(r, x, block), expected) << block;
    }
}

// Up or down, as `tactus live` converts a file for the device: unit gain to the pass edge, the
// images of a rise and the aliases of a fall in the stop band.
TEST(Resampler, ListeningBandConvertsEitherWay) {
    for (const auto& [in, out] : {std::pair{22050.0, 48000.0}, std::pair{44100.0, 48000.0},
                                  std::pair{96000.0, 48000.0}, std::pair{48000.0, 44100.0}}) {
        const double lower = std::min(in, out);
        const auto convert = [&](const std::vector<float>& x) {
            Resampler r;
            r.prepare(in, out, 512, Resampler::Band::listening);
            std::vector<float> y(static_cast<size_t>(static_cast<double>(x.size()) * out / in) +
                                 2048);
            size_t written = 0;
            for (size_t i = 0; i < x.size(); i += 512) {
                const int count = static_cast<int>(std::min<size_t>(512, x.size() - i));
                written += static_cast<size_t>(r.process(x.data() + i, count, y.data() + written));
            }
            y.resize(written);
            return y;
        };
        // A tone's amplitude in y at `hz`: correlated under a Hann window (no leakage).
        const auto amplitude = [&](const std::vector<float>& y, double hz) {
            double c = 0, s2 = 0, w_sum = 0;
            const size_t from = 2000, count = y.size() - from;
            for (size_t i = from; i < y.size(); ++i) {
                const double w =
                    0.5 - 0.5 * std::cos(2 * kPi * static_cast<double>(i - from) / count);
                const double phase = 2 * kPi * hz * static_cast<double>(i) / out;
                c += w * y[i] * std::cos(phase);
                s2 += w * y[i] * std::sin(phase);
                w_sum += w;
            }
            return 2 * std::hypot(c, s2) / w_sum;
        };
        const size_t n = static_cast<size_t>(0.25 * in);
        for (const double hz : {100.0, 1000.0, 0.98 * Resampler::kListeningPassEdge * lower}) {
            const auto y = convert(sine(hz, in, n));
            EXPECT_NEAR(gain_to_db(amplitude(y, hz)), 0.0, 0.01)
                << in << " -> " << out << ", " << hz << " Hz";
        }
        // Rising, a tone's image mirrors it around the input's Nyquist frequency; falling, a
        // tone above the output's folds back below it.
        const double above = in < out ? in - 0.3 * in : 0.5 * out + 0.4 * (0.5 * in - 0.5 * out);
        const double hz = in < out ? 0.3 * in : above;
        const auto y = convert(sine(hz, in, n));
        if (in < out) {  // the tone passes; the image at `above` does not
            EXPECT_LT(gain_to_db(amplitude(y, above)), -(Resampler::kListeningStopBandDb - 10))
                << in << " -> " << out << ": the image at " << above << " Hz";
        } else {
            EXPECT_LT(gain_to_db(rms(y, 2000) / std::sqrt(0.5)),
                      -(Resampler::kListeningStopBandDb - 10))
                << in << " -> " << out << ": " << hz << " Hz folds back";
        }
    }
}

}  // namespace
}  // namespace tactus
