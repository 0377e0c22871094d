// Resampler against closed forms: unit gain at DC and in the pass band, the stop band (what
// would alias) at least kStopBandDb - 5 dB down, output n at input position n * M / L (the count
// after any input), exact ratios for the usual rates and a bounded one otherwise, and the same
// output for any block split.
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

}  // namespace
}  // namespace tactus
