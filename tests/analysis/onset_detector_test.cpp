// OnsetDetector: clicks (single-sample impulses and short decaying noise bursts) over silence at
// exact sample times are each detected exactly once; the estimated onset_sample is within 1 ms
// of the truth; the decision comes after the onset and within 10 ms of it; nothing is detected
// in silence or in steady noise; min_interval suppresses a second hit closer than it.
#include "tactus/analysis/onset_detector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "support/signals.hpp"
#include "tactus/core/units.hpp"

namespace tactus {
namespace {

struct Detection {
    int64_t decided_at;  // frame end: the sample after the newest one analysed
    int64_t onset_sample;
};

std::vector<Detection> detect(const std::vector<float>& x, double fs,
                              const OnsetSettings& settings = {}, double hop_ms = 2.9,
                              double* largest_odf = nullptr) {
    const int hop = static_cast<int>(ms_to_samples(hop_ms, fs));
    OnsetDetector detector;
    detector.prepare({.sample_rate_hz = fs}, hop, settings);
    SampleHistory history;
    history.prepare(detector.span_samples());
    std::vector<Detection> found;
    for (size_t done = 0; done + static_cast<size_t>(hop) <= x.size(); done += hop) {
        history.write(x.data() + done, hop);
        const OnsetDecision d = detector.analyse(history, {0.0, 0.0});
        EXPECT_TRUE(std::isfinite(d.odf));
        if (largest_odf) *largest_odf = std::max(*largest_odf, d.odf);
        if (d.onset) found.push_back({history.written(), d.onset_sample});
    }
    return found;
}

enum class Click { impulse, burst };

// Clicks every ~250 ms at sample positions that do not fall on the hop grid.
std::vector<int64_t> place_clicks(std::vector<float>& x, double fs, Click kind, double amplitude,
                                  uint64_t seed) {
    test::Random random(seed);
    std::vector<int64_t> truth;
    for (int k = 0;; ++k) {
        const auto at = static_cast<int64_t>(std::llround((0.3 + 0.25 * k) * fs)) + 37 * k;
        if (at + static_cast<int64_t>(0.2 * fs) >= static_cast<int64_t>(x.size())) break;
        truth.push_back(at);
        if (kind == Click::impulse) {
            x[static_cast<size_t>(at)] = static_cast<float>(k % 2 ? -amplitude : amplitude);
        } else {
            const auto length = static_cast<int64_t>(0.05 * fs);
            for (int64_t i = 0; i < length; ++i)
                x[static_cast<size_t>(at + i)] = static_cast<float>(
                    amplitude * std::exp(-double(i) / (0.008 * fs)) * random.uniform(-1, 1));
        }
    }
    return truth;
}

void expect_each_found_once(const std::vector<int64_t>& truth, const std::vector<Detection>& found,
                            double fs, const std::string& what) {
    const double ms = fs / 1000.0;
    ASSERT_EQ(found.size(), truth.size()) << what;
    for (size_t i = 0; i < truth.size(); ++i) {
        EXPECT_NEAR(static_cast<double>(found[i].onset_sample), static_cast<double>(truth[i]),
                    1.0 * ms)
            << what << ": click " << i << " at sample " << truth[i];
        EXPECT_GT(found[i].decided_at, truth[i]) << what << ": click " << i;
        EXPECT_LE(found[i].decided_at - truth[i], 10.0 * ms) << what << ": click " << i;
    }
}

TEST(OnsetDetector, ClicksAreFoundOnceAtTheRightTime) {
    for (double fs : {44100.0, 48000.0, 96000.0}) {
        for (Click kind : {Click::impulse, Click::burst}) {
            // Quiet cases: a 0.1 impulse and a 0.02 burst (both detected with 2x to spare).
            for (double amplitude : {0.5, kind == Click::impulse ? 0.1 : 0.02}) {
                std::vector<float> x(static_cast<size_t>(3 * fs), 0.0f);
                const auto truth = place_clicks(x, fs, kind, amplitude, 17);
                const std::string what = std::string(kind == Click::impulse ? "impulse" : "burst") +
                                         " amplitude " + std::to_string(amplitude) + " at " +
                                         std::to_string(fs) + " Hz";
                expect_each_found_once(truth, detect(x, fs), fs, what);
            }
        }
    }
}

// The rise is measured over lags in time (OnsetDetector::kLagMs), not in frames: at a 1 ms hop
// the detection function rises as high as at the default hop (over one frame it would see a
// third of the rise), so the same thresholds find every quiet burst once, and decide sooner.
TEST(OnsetDetector, AShorterHopDecidesSoonerWithTheSameThresholds) {
    const double fs = 48000;
    std::vector<float> x(static_cast<size_t>(3 * fs), 0.0f);
    const auto truth = place_clicks(x, fs, Click::burst, 0.02, 17);
    const auto delay_ms = [&](const std::vector<Detection>& found) {
        double sum = 0;
        for (size_t i = 0; i < found.size(); ++i)
            sum += static_cast<double>(found[i].decided_at - truth[i]);
        return sum / static_cast<double>(found.size()) / fs * 1000;
    };
    double odf_default = 0, odf_1_ms = 0;
    const auto at_default = detect(x, fs, {}, 2.9, &odf_default);
    const auto at_1_ms = detect(x, fs, {}, 1.0, &odf_1_ms);
    EXPECT_GT(odf_1_ms, 0.7 * odf_default);
    expect_each_found_once(truth, at_1_ms, fs, "bursts at a 1 ms hop");
    ASSERT_FALSE(at_default.empty());
    EXPECT_LT(delay_ms(at_1_ms), delay_ms(at_default) - 0.5);
}

TEST(OnsetDetector, NothingInSilenceOrSteadyNoise) {
    const double fs = 48000;
    EXPECT_TRUE(detect(std::vector<float>(static_cast<size_t>(fs), 0.0f), fs).empty());
    // Steady noise: only its start is an onset.
    std::vector<float> x(static_cast<size_t>(2 * fs), 0.0f);
    const auto noise = test::white_noise(static_cast<size_t>(1.5 * fs), 4, 0.3);
    std::copy(noise.begin(), noise.end(), x.begin() + static_cast<long>(0.25 * fs));
    const auto found = detect(x, fs);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_NEAR(static_cast<double>(found[0].onset_sample), 0.25 * fs, 0.001 * fs);
}

TEST(OnsetDetector, MinIntervalSuppressesCloseHits) {
    const double fs = 48000;
    std::vector<float> x(static_cast<size_t>(fs), 0.0f);
    x[12000] = 0.5f;
    x[12000 + 960] = 0.5f;  // 20 ms later: inside the default 50 ms
    x[24000] = 0.5f;
    x[24000 + 3360] = 0.5f;  // 70 ms later: outside
    const auto found = detect(x, fs);
    ASSERT_EQ(found.size(), 3u);
    EXPECT_NEAR(static_cast<double>(found[0].onset_sample), 12000, 48);
    EXPECT_NEAR(static_cast<double>(found[1].onset_sample), 24000, 48);
    EXPECT_NEAR(static_cast<double>(found[2].onset_sample), 27360, 48);
}

TEST(OnsetDetector, ResetForgetsThePast) {
    const double fs = 48000;
    const int hop = 139;
    OnsetDetector detector;
    detector.prepare({.sample_rate_hz = fs}, hop, {});
    SampleHistory history;
    history.prepare(detector.span_samples());
    std::vector<float> click(static_cast<size_t>(hop), 0.0f);
    click[50] = 0.5f;
    const std::vector<float> silence(static_cast<size_t>(hop), 0.0f);
    auto first_onset_frame = [&] {
        for (int frame = 0; frame < 10; ++frame) {
            history.write(frame == 0 ? click.data() : silence.data(), hop);
            if (detector.analyse(history, {0.0, 0.0}).onset) return frame;
        }
        return -1;
    };
    const int a = first_onset_frame();
    detector.reset();
    history.reset();
    EXPECT_EQ(first_onset_frame(), a);
    EXPECT_GE(a, 0);
}

}  // namespace
}  // namespace tactus
