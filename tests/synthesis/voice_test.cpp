// Voice: silent (exact zeros) until triggered and again after the pulse has decayed; a pulse
// is exactly amplitude glide x envelope x sine started at phase 0 (no click); a retrigger while
// loud neither restarts the phase nor jumps; reset silences.
#include "tactus/synthesis/voice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/signals.hpp"
#include "tactus/core/units.hpp"
#include "tactus/synthesis/envelope.hpp"

namespace tactus {
namespace {

ControlFrame pulse(double frequency_hz, double amplitude, bool trigger) {
    ControlFrame f;
    f.frequency_hz = frequency_hz;
    f.amplitude = amplitude;
    f.trigger = trigger;
    f.attack_ms = 1;
    f.decay_ms = 100;
    f.sustain = 0;
    return f;
}

TEST(Voice, SilentWithoutTrigger) {
    Voice voice;
    voice.prepare({.sample_rate_hz = 48000}, 1000);
    voice.apply(pulse(100, 0.8, false));
    std::vector<float> out(48000, 1.0f);
    voice.process(out.data(), static_cast<int>(out.size()));
    for (float v : out) ASSERT_EQ(v, 0.0f);
}

// Sample by sample: amplitude glides to its target with a 1 ms one-pole, times the envelope,
// times a sine restarted at phase 0 by the trigger.
TEST(Voice, PulseIsGlideTimesEnvelopeTimesSineFromZeroPhase) {
    const double fs = 48000, f = 100, a = 0.5;
    Voice voice;
    voice.prepare({.sample_rate_hz = fs}, 1000);
    voice.apply(pulse(f, a, true));
    std::vector<float> out(static_cast<size_t>(2 * fs));
    voice.process(out.data(), static_cast<int>(out.size()));

    Envelope env;
    env.prepare({.sample_rate_hz = fs});
    env.set_shape(1, 100, 0);
    env.trigger();
    const double g = std::exp(-1.0 / (1e-3 * fs));
    double glide = 1.0;
    for (size_t i = 0; i < static_cast<size_t>(0.3 * fs); ++i) {
        const double expected = a * (1.0 - glide) * env.next() * std::sin(2 * kPi * f * i / fs);
        ASSERT_NEAR(out[i], expected, 1e-6) << "sample " << i;
        glide *= g;  // sample i holds the amplitude at time i / fs, then the glide steps
    }
    EXPECT_EQ(out[0], 0.0f);  // sin(0): no click at the start
    // Exact silence once the envelope is below -140 dB (100 ms per 60 dB: well within 1 s).
    for (size_t i = static_cast<size_t>(fs); i < out.size(); ++i) ASSERT_EQ(out[i], 0.0f) << i;
}

// The engine synthesises below the input rate (engine.hpp): the voice samples one continuous
// signal, so a pulse with glides rendered at 11.025 kHz matches every 4th sample at 44.1 kHz.
TEST(Voice, SameSignalAtAQuarterOfTheRate) {
    const auto render = [](double fs, int hop) {
        Voice voice;
        voice.prepare({.sample_rate_hz = fs}, 1000);
        std::vector<float> out;
        for (int frame = 0; frame < 60; ++frame) {
            std::vector<float> block(static_cast<size_t>(hop));
            voice.process(block.data(), hop);
            out.insert(out.end(), block.begin(), block.end());
            ControlFrame control =
                pulse(350.0 - 2 * frame, 0.5 * std::exp(-frame / 20.0), frame == 2);
            control.square_mix = 0.3;
            voice.apply(control);
        }
        return out;
    };
    const std::vector<float> full = render(44100, 128), quarter = render(11025, 32);
    double error = 0, energy = 0;
    for (size_t k = 0; k < quarter.size(); ++k) {
        error += std::pow(full[4 * k] - quarter[k], 2);
        energy += std::pow(full[4 * k], 2);
    }
    ASSERT_GT(energy, 0.0);
    EXPECT_LT(std::sqrt(error / energy), 2e-3);
}

TEST(Voice, RetriggerWhileLoudIsContinuous) {
    const double fs = 48000;
    Voice voice;
    voice.prepare({.sample_rate_hz = fs}, 1000);
    voice.apply(pulse(120, 0.8, true));
    std::vector<float> out(2400);
    voice.process(out.data(), 1200);
    voice.apply(pulse(120, 0.8, true));  // envelope still loud: phase continues
    voice.process(out.data() + 1200, 1200);
    // Largest step of an 0.8-amplitude 120 Hz sine: 0.8 * 2 pi 120 / fs ~ 0.0126.
    for (size_t i = 1; i < out.size(); ++i)
        ASSERT_LT(std::abs(out[i] - out[i - 1]), 0.02) << "jump at sample " << i;
}

TEST(Voice, ResetSilences) {
    Voice voice;
    voice.prepare({.sample_rate_hz = 48000}, 1000);
    voice.apply(pulse(100, 1.0, true));
    std::vector<float> out(480);
    voice.process(out.data(), 480);
    voice.reset();
    voice.process(out.data(), 480);
    for (float v : out) ASSERT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace tactus
