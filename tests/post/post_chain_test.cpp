// PostChain: the output never exceeds the ceiling (0 dB and lowered ceilings) on hostile input;
// the final safety clip does not have to act on full-scale signals (the limiter's 1 dB margin
// is meant to absorb the last band-limit's ringing); non-finite input gives finite output;
// latency is the limiter's; below the limiter threshold the chain is the product of its filters.
// Channel components: with flutter and pressure on the output still never exceeds the ceiling
// and the final clip does not act; the flutter passes 2-40 Hz (last high-pass at
// post.flutter_low_hz) through the 30 Hz peaking filter; the pressure arrives unfiltered; while
// they are off their buffers change nothing, bit for bit.
#include "tactus/post/post_chain.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "support/signals.hpp"
#include "tactus/core/units.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {

std::vector<std::pair<std::string, std::vector<float>>> loud_inputs(double fs) {
    std::vector<std::pair<std::string, std::vector<float>>> inputs;
    const auto n = static_cast<size_t>(2 * fs);
    inputs.emplace_back("noise +40 dB", test::white_noise(n, 21, 100.0));
    for (double f : {50.0, 120.0, 250.0, 400.0}) {
        std::vector<float> square(n);
        for (size_t i = 0; i < n; ++i)
            square[i] = std::fmod(double(i) * f / fs, 1.0) < 0.5 ? 1.0f : -1.0f;
        inputs.emplace_back("square " + std::to_string(f) + " Hz", square);
    }
    std::vector<float> impulses(n, 0.0f);
    for (size_t i = 100; i < n; i += 2400) impulses[i] = 50.0f;
    inputs.emplace_back("impulses", impulses);
    test::DrumSignal drums = test::drum_pattern(fs, 2.0, 3);
    for (auto& v : drums.audio) v *= 4.0f;
    inputs.emplace_back("drums +12 dB", drums.audio);
    return inputs;
}

TEST(PostChain, NeverAboveTheCeiling) {
    for (double ceiling_db : {0.0, -6.0, -20.0}) {
        for (double drive_db : {0.0, 20.0}) {
            Settings settings;
            settings.set(P::post_ceiling_db, ceiling_db);
            settings.set(P::post_drive_db, drive_db);
            const double fs = 48000;
            for (auto& [name, input] : loud_inputs(fs)) {
                PostChain chain;
                chain.prepare({.sample_rate_hz = fs}, settings);
                EXPECT_DOUBLE_EQ(chain.ceiling(), db_to_gain(ceiling_db));
                std::vector<float> y = input;
                chain.process(y.data(), static_cast<int>(y.size()));
                // Output samples are floats: the bound is the ceiling as a float sample value.
                EXPECT_LE(test::peak(y), static_cast<float>(chain.ceiling()))
                    << name << ", ceiling " << ceiling_db << " dB, drive " << drive_db << " dB";
            }
        }
    }
}

std::vector<std::pair<std::string, std::vector<float>>> full_scale_inputs(double fs) {
    std::vector<std::pair<std::string, std::vector<float>>> inputs;
    const auto n = static_cast<size_t>(2 * fs);
    inputs.emplace_back("noise 0 dBFS", test::white_noise(n, 22, 1.0));
    for (double f : {50.0, 120.0, 250.0, 400.0}) {
        std::vector<float> square(n);
        for (size_t i = 0; i < n; ++i)
            square[i] = std::fmod(double(i) * f / fs, 1.0) < 0.5 ? 1.0f : -1.0f;
        inputs.emplace_back("square " + std::to_string(f) + " Hz", square);
    }
    test::DrumSignal drums = test::drum_pattern(fs, 2.0, 3);
    const double scale = 1.0 / test::peak(drums.audio);
    for (auto& v : drums.audio) v = static_cast<float>(v * scale);
    inputs.emplace_back("drums 0 dBFS", drums.audio);
    return inputs;
}

// The header: the final clip "should not" act (the limiter sits 1 dB under the ceiling for the
// last band-limit's ringing); clipped_samples() counts when it does. Full-scale input, drive
// from 0 dB to +20 dB (the parameter allows +40).
TEST(PostChain, FinalClipDoesNotActOnFullScaleSignals) {
    for (double fs : {44100.0, 48000.0, 96000.0}) {
        for (double drive_db : {0.0, 12.0, 20.0}) {
            Settings settings;
            settings.set(P::post_drive_db, drive_db);
            for (auto& [name, input] : full_scale_inputs(fs)) {
                PostChain chain;
                chain.prepare({.sample_rate_hz = fs}, settings);
                std::vector<float> y = input;
                chain.process(y.data(), static_cast<int>(y.size()));
                EXPECT_EQ(chain.clipped_samples(), 0)
                    << name << " at " << fs << " Hz, drive " << drive_db << " dB";
            }
        }
    }
}

TEST(PostChain, NonFiniteInputGivesFiniteOutput) {
    PostChain chain;
    chain.prepare({.sample_rate_hz = 48000}, Settings{});
    std::vector<float> x = test::sine(200.0, 48000, 48000, 0.5);
    for (size_t i = 7; i < x.size(); i += 113)
        x[i] = i % 3 == 0   ? std::numeric_limits<float>::quiet_NaN()
               : i % 3 == 1 ? std::numeric_limits<float>::infinity()
                            : -std::numeric_limits<float>::infinity();
    chain.process(x.data(), static_cast<int>(x.size()));
    for (size_t i = 0; i < x.size(); ++i) {
        ASSERT_TRUE(std::isfinite(x[i])) << i;
        ASSERT_LE(std::abs(x[i]), 1.0f) << i;
    }
}

TEST(PostChain, LatencyIsTheLimiterLookahead) {
    for (double fs : {8000.0, 48000.0, 192000.0}) {
        Settings settings;
        settings.set(P::post_lookahead_ms, 2.0);
        PostChain chain;
        chain.prepare({.sample_rate_hz = fs}, settings);
        EXPECT_EQ(chain.latency(), std::llround(2e-3 * fs)) << fs;
    }
}

TEST(PostChain, QuietSineIsShapedOnlyByTheFiltersAndDrive) {
    // Below the limiter threshold the chain is linear: its gain is the product of the two
    // band-limits, the flattening filter and the drive.
    const double fs = 48000;
    for (double drive_db : {0.0, 6.0}) {
        Settings settings;
        settings.set(P::post_band_low_hz, 25);
        settings.set(P::post_band_high_hz, 900);
        settings.set(P::post_drive_db, drive_db);
        settings.set(P::post_limiter_threshold_db, -6);
        PostChain chain;
        chain.prepare({.sample_rate_hz = fs}, settings);
        BandLimit first, last;
        first.prepare({.sample_rate_hz = fs},
                      {.low_hz = 25, .high_hz = 900, .order = PostChain::kFirstBandOrder});
        last.prepare({.sample_rate_hz = fs},
                     {.low_hz = 25, .high_hz = 900, .order = PostChain::kLastBandOrder});
        for (double f : {40.0, 100.0, 250.0, 600.0}) {
            chain.reset();
            const double expected = first.magnitude_db(f) + last.magnitude_db(f) +
                                    chain.flattening().magnitude_db(f) + drive_db;
            const double measured = test::measured_gain_db(
                [&](float* x, int n) { chain.process(x, n); }, f, fs, 1.0, 0.5, 0.05);
            EXPECT_NEAR(measured, expected, 0.05) << f << " Hz, drive " << drive_db << " dB";
        }
    }
}

Settings with_channels(double pressure_weight) {
    Settings s;
    s.set(P::flutter_weight, 1.0);
    s.set(P::pressure_weight, pressure_weight);
    s.set(P::actuator_dc, 1);
    s.set(P::post_flutter_peak_db, -3);
    return s;
}

// Flutter and pressure at their largest: a full-scale 20 Hz square flutter, and the pressure
// at its weight x ceiling (what the mapping stage can send at most), stepping on and off.
void expect_ceiling_holds_with_channels(const std::vector<float>& carrier, double fs,
                                        double ceiling_db, double drive_db, double pressure_weight,
                                        bool expect_no_clipping, const std::string& what) {
    Settings settings = with_channels(pressure_weight);
    settings.set(P::post_ceiling_db, ceiling_db);
    settings.set(P::post_drive_db, drive_db);
    PostChain chain;
    chain.prepare({.sample_rate_hz = fs}, settings);
    const size_t n = carrier.size();
    std::vector<float> y = carrier, flutter(n), pressure(n);
    const double most_pressure = pressure_weight * chain.ceiling();
    for (size_t i = 0; i < n; ++i) {
        flutter[i] = std::fmod(double(i) * 20.0 / fs, 1.0) < 0.5 ? 1.0f : -1.0f;
        pressure[i] = (i / static_cast<size_t>(0.3 * fs)) % 2 ? float_at_most(most_pressure) : 0;
    }
    chain.process(y.data(), flutter.data(), pressure.data(), static_cast<int>(n));
    EXPECT_LE(test::peak(y), static_cast<float>(chain.ceiling())) << what;
    if (expect_no_clipping) {
        EXPECT_EQ(chain.clipped_samples(), 0) << what;
    }
}

TEST(PostChain, CeilingHoldsWithFlutterAndPressure) {
    const double fs = 48000;
    for (double pressure_weight : {0.1, 0.5}) {
        for (double ceiling_db : {0.0, -6.0, -20.0})
            for (double drive_db : {0.0, 20.0})
                for (auto& [name, input] : loud_inputs(fs))
                    expect_ceiling_holds_with_channels(
                        input, fs, ceiling_db, drive_db, pressure_weight, false,
                        name + ", ceiling " + std::to_string(ceiling_db) + " dB, drive " +
                            std::to_string(drive_db) + " dB, pressure " +
                            std::to_string(pressure_weight));
        for (double drive_db : {0.0, 12.0, 20.0})
            for (auto& [name, input] : full_scale_inputs(fs))
                expect_ceiling_holds_with_channels(input, fs, 0.0, drive_db, pressure_weight, true,
                                                   name + " (the final clip must not act), drive " +
                                                       std::to_string(drive_db) + " dB, pressure " +
                                                       std::to_string(pressure_weight));
    }
}

// Gain of the chain for a quiet sine entering as flutter (carrier and pressure silent).
double flutter_gain_db(PostChain& chain, double frequency_hz, double fs) {
    chain.reset();
    std::vector<float> flutter;
    return test::measured_gain_db(
        [&](float* x, int n) {
            flutter.assign(x, x + n);
            std::fill(x, x + n, 0.0f);
            chain.process(x, flutter.data(), nullptr, n);
        },
        frequency_hz, fs, 3.0, 1.0, 0.05);
}

TEST(PostChain, FlutterPassesTheNpiBandThroughThe30HzPeak) {
    const double npi_low_hz = perception::info(perception::Channel::NPI).range_low_hz;
    for (double fs : {4000.0, 48000.0}) {
        Settings settings = with_channels(0.0);
        settings.set(P::post_drive_db, 0);
        settings.set(P::post_flutter_low_hz, 1);
        PostChain chain;
        chain.prepare({.sample_rate_hz = fs}, settings);
        BandLimit last;
        last.prepare({.sample_rate_hz = fs}, {.low_hz = 1,
                                              .high_hz = settings[P::post_band_high_hz],
                                              .order = PostChain::kLastBandOrder});
        const BiquadCoefficients peak = BiquadCoefficients::peaking(30, 2, -3, fs);
        for (double f : {npi_low_hz, 8.0, 20.0, 30.0, 40.0}) {
            const double expected = last.magnitude_db(f) + peak.magnitude_db(f, fs);
            EXPECT_NEAR(flutter_gain_db(chain, f, fs), expected, 0.05) << f << " Hz at " << fs;
        }
        EXPECT_NEAR(flutter_gain_db(chain, 30, fs), -3.0, 0.1) << fs;
        EXPECT_GT(flutter_gain_db(chain, npi_low_hz, fs), -1.0) << "2 Hz must pass at " << fs;
    }
}

TEST(PostChain, PressureArrivesUnfiltered) {
    PostChain chain;
    chain.prepare({.sample_rate_hz = 48000}, with_channels(0.5));
    std::vector<float> carrier(48000, 0.0f), flutter(48000, 0.0f), pressure(48000, 0.3f);
    chain.process(carrier.data(), flutter.data(), pressure.data(), 48000);
    for (float v : carrier) ASSERT_EQ(v, 0.3f);
}

TEST(PostChain, ComponentsThatAreOffChangeNothing) {
    const double fs = 48000;
    test::DrumSignal drums = test::drum_pattern(fs, 2.0, 5);
    Settings settings;                      // flutter weight 0
    settings.set(P::pressure_weight, 0.5);  // a weight without a DC actuator
    settings.set(P::post_flutter_peak_db, 6);
    PostChain plain, given_buffers;
    plain.prepare({.sample_rate_hz = fs}, Settings{});
    given_buffers.prepare({.sample_rate_hz = fs}, settings);
    std::vector<float> a = drums.audio, b = drums.audio;
    std::vector<float> flutter = test::white_noise(a.size(), 9), pressure(a.size(), 0.4f);
    plain.process(a.data(), static_cast<int>(a.size()));
    given_buffers.process(b.data(), flutter.data(), pressure.data(), static_cast<int>(b.size()));
    ASSERT_GT(test::peak(a), 0.05);
    for (size_t i = 0; i < a.size(); ++i)
        ASSERT_EQ(std::bit_cast<uint32_t>(a[i]), std::bit_cast<uint32_t>(b[i])) << i;
}

TEST(PostChain, WithoutAnActuatorItIsExactlyThePapersFourStages) {
    // Bit for bit: band-limit (its high-pass: the carrier has nothing above the band), flattening,
    // limiter, band-limit and the final clip run by hand.
    const double fs = 44100;
    const Settings s;
    BandLimit first, last;
    first.prepare({.sample_rate_hz = fs}, {.low_hz = s[P::post_band_low_hz],
                                           .high_hz = s[P::post_band_high_hz],
                                           .order = PostChain::kFirstBandOrder,
                                           .low_pass = false});
    last.prepare({.sample_rate_hz = fs}, {.low_hz = s[P::post_band_low_hz],
                                          .high_hz = s[P::post_band_high_hz],
                                          .order = PostChain::kLastBandOrder});
    FlatteningFilter flatten;
    flatten.prepare({.sample_rate_hz = fs}, {.low_hz = s[P::post_band_low_hz],
                                             .high_hz = s[P::post_band_high_hz],
                                             .strength = s[P::post_flatten_strength],
                                             .range_db = s[P::post_flatten_range_db]});
    PeakLimiter limiter;
    limiter.prepare({.sample_rate_hz = fs}, s[P::post_lookahead_ms],
                    {.drive_db = s[P::post_drive_db],
                     .threshold_db = s[P::post_limiter_threshold_db],
                     .ceiling = db_to_gain(s[P::post_ceiling_db] - PostChain::kRingingMarginDb),
                     .release_ms = s[P::post_release_ms]});
    test::DrumSignal drums = test::drum_pattern(fs, 3.0, 5);
    std::vector<float> by_hand = drums.audio, chained = drums.audio;
    const int n = static_cast<int>(by_hand.size());
    first.process(by_hand.data(), n);
    flatten.process(by_hand.data(), n);
    limiter.process(by_hand.data(), n);
    last.process(by_hand.data(), n);
    for (auto& v : by_hand) v = std::clamp(v, -1.0f, 1.0f);
    PostChain chain;
    chain.prepare({.sample_rate_hz = fs}, s, nullptr);
    chain.process(chained.data(), n);
    EXPECT_EQ(chained, by_hand);
}

TEST(PostChain, ActuatorCompensationAndMaxDrive) {
    const double fs = 48000;
    const ActuatorProfile lra = load_actuator(resolve_actuator("lra-175"));
    Settings settings;
    settings.set(P::post_drive_db, 20);
    for (auto& [name, input] : loud_inputs(fs)) {
        PostChain chain;
        chain.prepare({.sample_rate_hz = fs}, settings, &lra);
        EXPECT_DOUBLE_EQ(chain.ceiling(), lra.max_drive);
        std::vector<float> y = input;
        chain.process(y.data(), static_cast<int>(y.size()));
        EXPECT_LE(test::peak(y), static_cast<float>(lra.max_drive)) << name;
    }
    // Below the limiter threshold the compensation adds its own response, nothing else.
    const ActuatorProfile voice_coil = load_actuator(resolve_actuator("voice-coil"));
    Settings quiet;
    quiet.set(P::post_drive_db, 0);
    PostChain plain, compensated;
    plain.prepare({.sample_rate_hz = fs}, quiet);
    compensated.prepare({.sample_rate_hz = fs}, quiet, &voice_coil);
    ActuatorCompensation compensation;
    compensation.prepare({.sample_rate_hz = fs}, voice_coil);
    for (double f : {40.0, 200.0, 600.0}) {
        const auto gain = [&](PostChain& chain) {
            return test::measured_gain_db([&](float* x, int n) { chain.process(x, n); }, f, fs, 1.0,
                                          0.5, 0.02);
        };
        EXPECT_NEAR(gain(compensated) - gain(plain), compensation.magnitude_db(f), 0.05) << f;
    }
}

}  // namespace
}  // namespace tactus
