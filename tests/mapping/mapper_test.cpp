// Pulse frequency: with mapping.frequency.hold on, an onset's frame maps the frequency without
// smoothing (a pulse after silence starts at its own pitch, not at the floor), the pulse follows
// the mapping for settle_ms and then keeps its frequency until the next onset; with hold off the
// frequency is smoothed throughout, onsets or not.
// Mapper: above the loudness gate the three mappings and the onset trigger pass; below it the
// amplitude is 0, triggers are dropped, and frequency and square mix hold their last values;
// envelope settings and the frame's sample are carried into every ControlFrame.
// Channel components: flutter and pressure are exactly 0 while off (no weight; pressure also
// without actuator.dc); flutter = weight x level, times 21/140 with equalisation; flutter rate
// on its log scale; pressure is a fraction of the ceiling, in steps with hysteresis.
#include "tactus/mapping/mapper.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tactus {
namespace {

// Every mapping parameter set explicitly (the defaults are tuned elsewhere).
Settings immediate_settings() {
    Settings s;
    s.set(P::mapping_gate_db, -70);
    s.set(P::amplitude_source, static_cast<double>(FeatureSource::loudness_db));
    s.set(P::amplitude_in_min, -60);
    s.set(P::amplitude_in_max, 0);
    s.set(P::amplitude_out_min, 0.03);
    s.set(P::amplitude_out_max, 1);
    s.set(P::amplitude_curve, static_cast<double>(MappingCurve::exp));
    s.set(P::frequency_source, static_cast<double>(FeatureSource::brightness_hz));
    s.set(P::frequency_in_min, 150);
    s.set(P::frequency_in_max, 6000);
    s.set(P::frequency_out_min, 50);
    s.set(P::frequency_out_max, 320);
    s.set(P::frequency_curve, static_cast<double>(MappingCurve::log));
    s.set(P::square_mix_source, static_cast<double>(FeatureSource::tonality));
    s.set(P::square_mix_in_min, 0.3);
    s.set(P::square_mix_in_max, 0.9);
    s.set(P::square_mix_out_min, 0);
    s.set(P::square_mix_out_max, 1);
    s.set(P::square_mix_curve, static_cast<double>(MappingCurve::lin));
    s.set(P::frequency_smoothing_ms, 0);
    s.set(P::square_mix_smoothing_ms, 0);
    s.set(P::amplitude_smoothing_ms, 0);
    s.set(P::envelope_attack_ms, 2);
    s.set(P::envelope_decay_ms, 300);
    s.set(P::envelope_sustain, 0.25);
    return s;
}

Features frame(int64_t end, double loudness_db, double brightness_hz, double noisiness,
               bool onset) {
    Features f;
    f.frame_end_sample = end;
    f.loudness_db = loudness_db;
    f.brightness_hz = brightness_hz;
    f.noisiness = noisiness;
    f.onset = onset;
    f.onset_sample = end - 10;
    return f;
}

TEST(Mapper, AboveTheGateEverythingPasses) {
    Mapper mapper;
    mapper.prepare(immediate_settings(), 345.0);
    const ControlFrame c = mapper.map(frame(1000, -30, std::sqrt(150.0 * 6000.0), 0.4, true));
    EXPECT_EQ(c.sample, 1000);
    EXPECT_NEAR(c.amplitude, std::sqrt(0.03), 1e-9);             // exp: -30 dB of -60...0
    EXPECT_NEAR(c.frequency_hz, std::sqrt(50.0 * 320.0), 1e-9);  // log: geometric middle
    EXPECT_NEAR(c.square_mix, (0.6 - 0.3) / (0.9 - 0.3), 1e-9);  // tonality 0.6
    EXPECT_TRUE(c.trigger);
    EXPECT_EQ(c.attack_ms, 2);
    EXPECT_EQ(c.decay_ms, 300);
    EXPECT_EQ(c.sustain, 0.25);
}

TEST(Mapper, BelowTheGateSilentNoTriggerAndHeldCarrier) {
    Mapper mapper;
    mapper.prepare(immediate_settings(), 345.0);
    const ControlFrame loud = mapper.map(frame(100, -20, 1000, 0.5, false));
    EXPECT_GT(loud.amplitude, 0.0);
    for (double quiet_db : {-70.01, -90.0, -120.0}) {
        const ControlFrame quiet = mapper.map(frame(200, quiet_db, 5000, 0.05, true));
        EXPECT_EQ(quiet.amplitude, 0.0) << quiet_db;
        EXPECT_FALSE(quiet.trigger) << quiet_db;
        EXPECT_EQ(quiet.frequency_hz, loud.frequency_hz) << quiet_db;
        EXPECT_EQ(quiet.square_mix, loud.square_mix) << quiet_db;
        EXPECT_EQ(quiet.sample, 200);
        EXPECT_EQ(quiet.decay_ms, 300);
    }
    // Exactly at the gate counts as above it.
    const ControlFrame at_gate = mapper.map(frame(300, -70, 1000, 0.5, true));
    EXPECT_GT(at_gate.amplitude, 0.0);
    EXPECT_TRUE(at_gate.trigger);
}

TEST(Mapper, SmoothedAmplitudeRestartsFromZeroAfterTheGate) {
    Settings s = immediate_settings();
    s.set(P::amplitude_smoothing_ms, 100);
    Mapper mapper;
    mapper.prepare(s, 100.0);  // 10 frames per time constant
    double a = 0.0;
    for (int i = 0; i < 200; ++i) a = mapper.map(frame(i, 0, 1000, 0.5, false)).amplitude;
    EXPECT_NEAR(a, 1.0, 1e-6);
    EXPECT_EQ(mapper.map(frame(200, -100, 1000, 0.5, false)).amplitude, 0.0);
    const double first = mapper.map(frame(201, 0, 1000, 0.5, false)).amplitude;
    EXPECT_NEAR(first, 1.0 - std::exp(-0.1), 1e-9);
}

TEST(Mapper, ResetStartsTheCarrierAtTheMappingsOfZero) {
    Mapper mapper;
    mapper.prepare(immediate_settings(), 345.0);
    // Before any sound the carrier holds what each mapping gives an input of 0.
    const ControlFrame c = mapper.map(frame(0, -120, 0, 0, false));
    EXPECT_EQ(c.amplitude, 0.0);
    EXPECT_NEAR(c.frequency_hz, 50.0, 1e-9);
    EXPECT_NEAR(c.square_mix, 0.0, 1e-12);
}

// Flutter and pressure mapped straight from loudness (lin, -60 ... 0 dB -> 0 ... 1) and the
// flutter rate from brightness (log, 100 ... 6400 Hz -> 5 ... 40 Hz), no smoothing.
Settings channel_settings() {
    Settings s = immediate_settings();
    for (P first : {P::flutter_level_source, P::pressure_level_source}) {
        const auto at = [&](int k) { return static_cast<P>(static_cast<int>(first) + k); };
        s.set(at(0), static_cast<double>(FeatureSource::loudness_db));
        s.set(at(1), -60);
        s.set(at(2), 0);
        s.set(at(3), 0);
        s.set(at(4), 1);
        s.set(at(5), static_cast<double>(MappingCurve::lin));
        s.set(at(6), 0);
    }
    s.set(P::flutter_rate_source, static_cast<double>(FeatureSource::brightness_hz));
    s.set(P::flutter_rate_in_min, 100);
    s.set(P::flutter_rate_in_max, 6400);
    s.set(P::flutter_rate_out_min, 5);
    s.set(P::flutter_rate_out_max, 40);
    s.set(P::flutter_rate_curve, static_cast<double>(MappingCurve::log));
    s.set(P::flutter_rate_smoothing_ms, 0);
    return s;
}

TEST(Mapper, ChannelComponentsAreExactlyZeroWhileOff) {
    Settings s = channel_settings();
    s.set(P::pressure_weight, 0.5);  // a weight, but no DC actuator
    Mapper mapper;
    mapper.prepare(s, 345.0);
    const ControlFrame c = mapper.map(frame(100, -6, 800, 0.5, true));
    EXPECT_EQ(c.flutter_amplitude, 0.0);
    EXPECT_EQ(c.pressure, 0.0);
    EXPECT_GT(c.amplitude, 0.0);
}

TEST(Mapper, FlutterIsWeightTimesLevelAndEqualisedByInnervation) {
    Settings s = channel_settings();
    s.set(P::flutter_weight, 0.8);
    Mapper mapper;
    mapper.prepare(s, 345.0);
    ControlFrame c = mapper.map(frame(100, -15, 800, 0.5, false));
    EXPECT_NEAR(c.flutter_amplitude, 0.8 * 0.75, 1e-12);
    // 800 Hz, half way up 100 ... 6400 on a log scale: the geometric middle of 5 ... 40 Hz.
    EXPECT_NEAR(c.flutter_hz, std::sqrt(5.0 * 40.0), 1e-9);
    s.set(P::flutter_equalize, 1);
    mapper.prepare(s, 345.0);
    c = mapper.map(frame(100, -15, 800, 0.5, false));
    EXPECT_NEAR(c.flutter_amplitude, 0.8 * 0.75 * 21.0 / 140.0, 1e-12);
    // Below the gate the flutter stops and its rate holds.
    const ControlFrame quiet = mapper.map(frame(200, -100, 6400, 0.5, false));
    EXPECT_EQ(quiet.flutter_amplitude, 0.0);
    EXPECT_EQ(quiet.flutter_hz, c.flutter_hz);
}

TEST(Mapper, PressureIsAFractionOfTheCeiling) {
    Settings s = channel_settings();
    s.set(P::pressure_weight, 0.4);
    s.set(P::actuator_dc, 1);
    s.set(P::post_ceiling_db, -6);
    Mapper mapper;
    mapper.prepare(s, 345.0);
    EXPECT_NEAR(mapper.map(frame(100, -15, 800, 0.5, false)).pressure,
                0.4 * 0.75 * std::pow(10.0, -6.0 / 20), 1e-12);
    EXPECT_EQ(mapper.map(frame(101, -100, 800, 0.5, false)).pressure, 0.0);
    // An actuator's max drive lowers the ceiling (PostChain::ceiling()): the pressure follows.
    mapper.prepare(s, {.frames_per_second = 345.0, .output_ceiling = 0.25});
    EXPECT_NEAR(mapper.map(frame(100, -15, 800, 0.5, false)).pressure, 0.4 * 0.75 * 0.25, 1e-12);
}

TEST(Mapper, PressureStepsWithHysteresis) {
    Settings s = channel_settings();
    s.set(P::pressure_weight, 0.5);
    s.set(P::actuator_dc, 1);
    s.set(P::pressure_steps, 4);
    Mapper mapper;
    mapper.prepare(s, 345.0);
    const auto pressure_at = [&](double level) {
        return mapper.map(frame(0, -60 + 60 * level, 800, 0.5, false)).pressure;
    };
    EXPECT_EQ(pressure_at(0.1), 0.0);
    EXPECT_NEAR(pressure_at(0.3), 0.5 * 0.25, 1e-12);   // 1.2 steps: step 1
    EXPECT_NEAR(pressure_at(0.36), 0.5 * 0.25, 1e-12);  // 1.44: still 1
    EXPECT_NEAR(pressure_at(0.39), 0.5 * 0.25, 1e-12);  // 1.56: within the hysteresis
    EXPECT_NEAR(pressure_at(0.42), 0.5 * 0.5, 1e-12);   // 1.68: step 2
    EXPECT_NEAR(pressure_at(0.36), 0.5 * 0.5, 1e-12);   // 1.44: held at 2
    EXPECT_NEAR(pressure_at(0.32), 0.5 * 0.25, 1e-12);  // 1.28: back to 1
    EXPECT_NEAR(pressure_at(1.0), 0.5, 1e-12);
}

// Brightness -> frequency as in immediate_settings (log, 150 ... 6000 Hz -> 50 ... 320 Hz),
// smoothed over 5 ms, 345 frames per second (2.9 ms apart).
Settings pulse_settings(bool hold, double settle_ms) {
    Settings s = immediate_settings();
    s.set(P::frequency_smoothing_ms, 5);
    s.set(P::frequency_hold, hold ? 1 : 0);
    s.set(P::frequency_settle_ms, settle_ms);
    return s;
}

double mapped_hz(double brightness_hz) {
    return 50.0 * std::pow(320.0 / 50.0, std::log(brightness_hz / 150.0) / std::log(40.0));
}

TEST(Mapper, HeldPulseStartsAtItsOwnFrequencyAndKeepsIt) {
    Mapper mapper;
    mapper.prepare(pulse_settings(true, 0), 345.0);
    for (int i = 0; i < 20; ++i) mapper.map(frame(i, -30, 150, 0.5, false));  // at the floor
    // A bright hit: its onset frame is at its own frequency, not smoothed up from 50 Hz.
    EXPECT_NEAR(mapper.map(frame(20, -20, 4000, 0.5, true)).frequency_hz, mapped_hz(4000), 1e-9);
    // Its body darkens; the pulse keeps the onset's frequency.
    for (int i = 21; i < 60; ++i)
        EXPECT_NEAR(mapper.map(frame(i, -25, 300, 0.5, false)).frequency_hz, mapped_hz(4000), 1e-9);
    // Below the gate it holds too, and the next onset takes its own.
    EXPECT_NEAR(mapper.map(frame(60, -100, 6000, 0.5, false)).frequency_hz, mapped_hz(4000), 1e-9);
    EXPECT_NEAR(mapper.map(frame(61, -20, 200, 0.5, true)).frequency_hz, mapped_hz(200), 1e-9);
    EXPECT_NEAR(mapper.map(frame(62, -20, 5000, 0.5, false)).frequency_hz, mapped_hz(200), 1e-9);
}

TEST(Mapper, HeldPulseFollowsForTheSettleTimeThenHolds) {
    Mapper mapper;
    mapper.prepare(pulse_settings(true, 10), 345.0);  // frames 0 ... 3 after the onset follow
    EXPECT_NEAR(mapper.map(frame(0, -20, 4000, 0.5, true)).frequency_hz, mapped_hz(4000), 1e-9);
    const double body_hz[] = {2000, 1000, 600, 300, 200};
    for (int k = 1; k <= 3; ++k)  // 2.9, 5.8, 8.7 ms: unsmoothed
        EXPECT_NEAR(mapper.map(frame(k, -20, body_hz[k - 1], 0.5, false)).frequency_hz,
                    mapped_hz(body_hz[k - 1]), 1e-9)
            << k;
    for (int k = 4; k <= 5; ++k)  // 11.6 ms on: held at the last followed frame's
        EXPECT_NEAR(mapper.map(frame(k, -20, body_hz[k - 1], 0.5, false)).frequency_hz,
                    mapped_hz(600), 1e-9)
            << k;
}

TEST(Mapper, WithoutHoldTheFrequencyIsSmoothedThroughOnsets) {
    Mapper mapper;
    mapper.prepare(pulse_settings(false, 0), 345.0);
    for (int i = 0; i < 20; ++i) mapper.map(frame(i, -30, 150, 0.5, false));
    const double onset_hz = mapper.map(frame(20, -20, 4000, 0.5, true)).frequency_hz;
    const double a = std::exp(-1000.0 / 345.0 / 5.0);  // one-pole over one frame
    EXPECT_NEAR(onset_hz, mapped_hz(4000) + a * (50.0 - mapped_hz(4000)), 1e-9);
    EXPECT_GT(mapper.map(frame(21, -20, 4000, 0.5, false)).frequency_hz, onset_hz);
}

// By drum part: nothing changes until the pulse's part is decided; from then the part's gain,
// brightness (through the frequency mapping) and decay shape it, and a new onset forgets them.
TEST(Mapper, APartShapesItsPulseOnceDecided) {
    Settings s = immediate_settings();
    s.set(P::parts_kick_gain_db, -6);
    s.set(P::parts_kick_brightness_hz, 150);  // the frequency mapping's in_min: out_min
    s.set(P::parts_kick_decay_ms, 400);
    s.set(P::parts_other_gain_db, -60);  // off
    Mapper m;
    m.prepare(s, 100.0);
    Features onset = frame(100, -10, 3000, 0.5, true);
    const ControlFrame at_onset = m.map(onset);
    Features decided = frame(200, -10, 3000, 0.5, false);
    decided.part = DrumPart::kick;
    decided.part_decided = true;
    const ControlFrame kick = m.map(decided);
    EXPECT_NEAR(kick.amplitude, at_onset.amplitude * std::pow(10.0, -6.0 / 20), 1e-9);
    EXPECT_NEAR(kick.frequency_hz, 50.0, 1e-9);
    EXPECT_EQ(kick.decay_ms, 400.0);
    EXPECT_NEAR(m.map(frame(300, -10, 3000, 0.5, false)).frequency_hz, 50.0, 1e-9);  // kept

    const ControlFrame next = m.map(frame(400, -10, 3000, 0.5, true));  // a new pulse
    EXPECT_NEAR(next.amplitude, at_onset.amplitude, 1e-9);
    EXPECT_EQ(next.decay_ms, 300.0);
    Features other = frame(500, -10, 3000, 0.5, false);
    other.part = DrumPart::other;
    other.part_decided = true;
    EXPECT_EQ(m.map(other).amplitude, 0.0);  // -60 dB: off
}

}  // namespace
}  // namespace tactus
