// Sensation-level meter on synthetic signals with known displacement: a steady sine reads its
// level minus the channel threshold; a 10 Hz sine engages NPI and not P; short bursts follow
// P's temporal summation; contact area shifts P; a static offset reaches NPIII only through an
// actuator that can hold one.
#include "tactus/perception/meter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/signals.hpp"
#include "tactus/io/actuator_file.hpp"

namespace tactus::perception {
namespace {

constexpr double kFs = 48000;

// Readings for `x` through a calibration; the reading at `at_s` and the largest per channel.
struct Metered {
    std::vector<MeterReading> readings;
    MeterReading at(double t) const {
        for (const auto& r : readings)
            if (r.time_s >= t - 1e-9) return r;
        return readings.back();
    }
    double max(Channel c) const {
        double m = 0;
        for (const auto& r : readings) m = std::max(m, r.level_db[static_cast<int>(c)]);
        return m;
    }
};

Metered meter(const std::vector<float>& x, const SensationMeter::Calibration& calibration,
              double area_cm2 = kReferenceAreaCm2, double sample_rate_hz = kFs) {
    SensationMeter m;
    m.prepare(sample_rate_hz, calibration, area_cm2);
    Metered run;
    const auto keep = [&](const MeterReading& r) { run.readings.push_back(r); };
    for (size_t i = 0; i < x.size(); i += 1000)
        m.write(x.data() + i, static_cast<int>(std::min<size_t>(1000, x.size() - i)), keep);
    m.finish(keep);
    return run;
}

const auto flat_10um = [](double f) { return f > 0 ? 10.0 : 0.0; };
double level(Channel c, const MeterReading& r) {
    return r.level_db[static_cast<int>(c)];
}

TEST(SensationMeter, SteadySineReadsLevelMinusThreshold) {
    for (double f : {40.0, 80.0, 250.0, 400.0, 1000.0}) {
        // 0.5 full scale x 10 um = 5 um peak: 20 log10(5) = 14 dB re 1 um.
        const auto x = test::sine(f, kFs, static_cast<size_t>(3 * kFs), 0.5);
        const MeterReading r = meter(x, flat_10um).at(2.8);
        const double level_db = 20 * std::log10(5.0);
        EXPECT_NEAR(level(Channel::P, r), level_db - threshold_db(Channel::P, f), 0.5) << f;
        EXPECT_NEAR(level(Channel::NPII, r),
                    std::max(0.0, level_db - threshold_db(Channel::NPII, f)), 0.5)
            << f;
        EXPECT_EQ(level(Channel::NPIII, r), 0.0) << f;
        // P alone: the combination is P's level again, up to the rounding of its dB -> magnitude
        // -> dB round trip (an ulp below it on aarch64).
        EXPECT_GE(r.combined_db, level(Channel::P, r) - 1e-9);
    }
}

// The channels read the signal at SensationMeter::kRateHz: a sweep and a pulse train read the same
// from 8 to 96 kHz, reading for reading (a pulse's first reading, where its rise meets the
// window's edge, is the most sensitive to the reduction's fraction of a sample).
TEST(SensationMeter, ReadsTheSameAtEveryInputRate) {
    const auto signal = [](double fs) {
        std::vector<float> x(static_cast<size_t>(4 * fs));
        for (size_t i = 0; i < x.size(); ++i) {
            const double t = static_cast<double>(i) / fs;
            const double sweep = std::sin(2 * M_PI * (20 * t + 60 * t * t));  // 20-500 Hz
            const double pulse = std::fmod(t, 0.25) < 0.03 ? std::sin(2 * M_PI * 180 * t) : 0.0;
            x[i] = static_cast<float>(0.4 * sweep + 0.4 * pulse);
        }
        return x;
    };
    const Metered reference = meter(signal(8000), flat_10um, kReferenceAreaCm2, 8000);
    for (const double fs : {16000.0, 44100.0, 48000.0, 96000.0}) {
        const Metered run = meter(signal(fs), flat_10um, kReferenceAreaCm2, fs);
        ASSERT_EQ(run.readings.size(), reference.readings.size()) << fs;
        double worst = 0;
        for (size_t i = 0; i < run.readings.size(); ++i) {
            EXPECT_NEAR(run.readings[i].time_s, reference.readings[i].time_s, 1e-9);
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::abs(run.readings[i].level_db[c] -
                                                 reference.readings[i].level_db[c]));
        }
        EXPECT_LT(worst, 0.2) << fs;
    }
}

TEST(SensationMeter, TenHertzEngagesNpiNotP) {
    // 15 dB above NPI's threshold at 10 Hz; P's threshold there is ~32 dB re 1 um.
    const double level_db = threshold_db(Channel::NPI, 10) + 15;
    const double amplitude = std::pow(10, level_db / 20) / 100.0;  // through 100 um full scale
    const auto x = test::sine(10, kFs, static_cast<size_t>(3 * kFs), amplitude);
    const Metered run = meter(x, [](double f) { return f > 0 ? 100.0 : 0.0; });
    EXPECT_NEAR(level(Channel::NPI, run.at(2.8)), 15.0, 0.5);
    EXPECT_EQ(run.max(Channel::P), 0.0);
    EXPECT_EQ(run.max(Channel::NPII), 0.0);
    EXPECT_EQ(run.max(Channel::NPIII), 0.0);
}

TEST(SensationMeter, PBurstsFollowTemporalSummation) {
    // A 250 Hz burst of d seconds reads its level minus the threshold for that duration.
    for (double d : {0.05, 0.1, 0.25, 0.5}) {
        std::vector<float> x(static_cast<size_t>(3 * kFs), 0.0f);
        const auto burst = test::sine(250, kFs, static_cast<size_t>(d * kFs), 0.5);
        std::copy(burst.begin(), burst.end(), x.begin() + static_cast<long>(kFs));
        const double expected =
            20 * std::log10(5.0) - threshold_db(Channel::P, 250, {.duration_s = d});
        EXPECT_NEAR(meter(x, flat_10um).max(Channel::P), expected, 1.0) << d << " s";
    }
}

// Temporal summation lowers the threshold of longer stimuli; it does not make a sensation outlast
// its stimulus: a 50 ms burst at 1 s reads P only while it is inside P's window.
TEST(SensationMeter, PFollowsTheStimulusInTime) {
    std::vector<float> x(static_cast<size_t>(3 * kFs), 0.0f);
    const auto burst = test::sine(250, kFs, static_cast<size_t>(0.05 * kFs), 0.5);
    std::copy(burst.begin(), burst.end(), x.begin() + static_cast<long>(kFs));
    double first_s = 0, last_s = 0;
    for (const auto& r : meter(x, flat_10um).readings)
        if (level(Channel::P, r) > 0) {
            if (first_s == 0) first_s = r.time_s;
            last_s = r.time_s;
        }
    const double window_s = SensationMeter::kHopsPerWindow *
                            SensationMeter::kHopSteps[static_cast<int>(Channel::P)] *
                            SensationMeter::kStepS;
    EXPECT_GT(first_s, 1.0);
    EXPECT_LE(first_s, 1.05 + SensationMeter::kHopSteps[0] * SensationMeter::kStepS);
    EXPECT_LE(last_s, 1.05 + window_s + SensationMeter::kStepS) << "window " << window_s << " s";
}

TEST(SensationMeter, SmallerContactRaisesPThreshold) {
    const auto x = test::sine(250, kFs, static_cast<size_t>(3 * kFs), 0.5);
    const double large = level(Channel::P, meter(x, flat_10um, 2.9).at(2.8));
    const double small = level(Channel::P, meter(x, flat_10um, 0.725).at(2.8));
    EXPECT_NEAR(large - small, 6.0, 0.1);  // two halvings, 3 dB each
}

TEST(SensationMeter, StaticOffsetNeedsDcCapability) {
    // 0.8 full scale held for 7 s through 200 um: 44 dB re 1 um, ~14 dB above NPIII's threshold
    // if the actuator can hold it.
    const std::vector<float> x(static_cast<size_t>(7 * kFs), 0.8f);
    const std::string body =
        "displacement_um = 200\nreference_hz = 100\nband_low_hz = 20\nband_high_hz = 1000\n";
    const ActuatorProfile ac = parse_actuator(body, "ac.toml");
    const ActuatorProfile dc = parse_actuator(body + "dc = true\n", "dc.toml");
    const Metered through_ac = meter(x, [&](double f) { return ac.displacement_um_at(f); });
    EXPECT_EQ(through_ac.max(Channel::NPIII), 0.0);
    const Metered through_dc = meter(x, [&](double f) { return dc.displacement_um_at(f); });
    EXPECT_GT(level(Channel::NPIII, through_dc.at(6.5)), 10.0);
    EXPECT_LT(level(Channel::NPIII, through_dc.at(6.5)), 14.0 + 3.0 + 1.0);  // offset reads +3 dB
    // The shipped voice coil, like the paper's actuators, cannot engage NPIII (paper §5.4).
    const ActuatorProfile voice_coil = load_actuator(resolve_actuator("voice-coil"));
    EXPECT_EQ(
        meter(x, [&](double f) { return voice_coil.displacement_um_at(f); }).max(Channel::NPIII),
        0.0);
}

TEST(SensationMeter, SilenceEngagesNothing) {
    const std::vector<float> x(static_cast<size_t>(2 * kFs), 0.0f);
    const Metered run = meter(x, flat_10um);
    ASSERT_GT(run.readings.size(), 190u);
    for (const auto& c : kChannels) EXPECT_EQ(run.max(c.channel), 0.0);
    EXPECT_NEAR(run.readings[99].time_s, 1.0, 1e-9);  // causal readings every 10 ms
}

// Two meters of disjoint channels (the studio's and the report's two threads) read, channel for
// channel, what one meter of all four reads, bit for bit, reading for reading.
TEST(SensationMeter, DisjointChannelsReadAsOneMeter) {
    std::vector<float> x = test::white_noise(static_cast<size_t>(6 * kFs), 7, 0.3);
    const std::vector<float> tone = test::sine(12, kFs, x.size(), 0.5);
    for (size_t i = 0; i < x.size(); ++i) x[i] += tone[i];
    const Metered whole = meter(x, flat_10um);
    std::vector<MeterReading> parts[2];
    const SensationMeter::Channels channels[2] = {{true, false, true, false},
                                                  {false, true, false, true}};
    for (int p = 0; p < 2; ++p) {
        SensationMeter m;
        m.prepare(kFs, flat_10um, kReferenceAreaCm2, channels[p]);
        const auto keep = [&](const MeterReading& r) { parts[p].push_back(r); };
        for (size_t i = 0; i < x.size(); i += 1000)
            m.write(x.data() + i, static_cast<int>(std::min<size_t>(1000, x.size() - i)), keep);
        m.finish(keep);
    }
    ASSERT_EQ(parts[0].size(), whole.readings.size());
    ASSERT_EQ(parts[1].size(), whole.readings.size());
    int engaged = 0;
    for (size_t i = 0; i < whole.readings.size(); ++i)
        for (int c = 0; c < 4; ++c) {
            const int p = channels[0][static_cast<size_t>(c)] ? 0 : 1;
            ASSERT_EQ(parts[p][i].time_s, whole.readings[i].time_s);
            ASSERT_EQ(parts[p][i].level_db[c], whole.readings[i].level_db[c]) << i << " " << c;
            ASSERT_EQ(parts[1 - p][i].level_db[c], 0.0);  // not metered: reads 0
            engaged += whole.readings[i].level_db[c] > 0;
        }
    EXPECT_GT(engaged, 1000);
}

TEST(MeterSummariser, MaxEngagedFractionAndMedian) {
    MeterSummariser s;
    for (double v : {0.0, 0.0, 5.0, 10.0, 20.0}) {
        MeterReading r;
        r.level_db = {v, 0, 0, 0};
        r.combined_db = v;
        s.add(r);
    }
    const MeterSummary m = s.summary();
    EXPECT_EQ(m.readings, 5);
    EXPECT_EQ(m.channels[0].max_db, 20.0);
    EXPECT_NEAR(m.channels[0].engaged_fraction, 0.6, 1e-12);
    EXPECT_EQ(m.channels[0].median_engaged_db, 10.0);
    EXPECT_EQ(m.channels[1].engaged_fraction, 0.0);
    EXPECT_EQ(m.combined.max_db, 20.0);
}

}  // namespace
}  // namespace tactus::perception
