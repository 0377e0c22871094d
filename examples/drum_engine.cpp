// What a front end does with the tactus engine, in one file: a synthetic drum loop (a kick on
// every beat at 120 BPM) goes through the engine at 48 kHz in 64-frame blocks, as an audio
// callback would send it, to two actuators (the second 6 dB down and 5 ms late); meanwhile a
// control thread turns the envelope's decay and the drive, as a knob or an OSC message would,
// and a reader thread takes the analysis frames off the engine's queue. Prints what it found;
// exits 1 if the kicks did not become vibration.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tactus/engine/engine.hpp>
#include <thread>
#include <vector>

int main() {
    constexpr double kRateHz = 48000;
    constexpr int kBlock = 64;
    constexpr double kSeconds = 4;

    // A kick: a sine falling from 150 Hz to 60 Hz, decaying over 120 ms, every 0.5 s.
    std::vector<float> music(static_cast<size_t>(kSeconds * kRateHz));
    for (size_t i = 0; i < music.size(); ++i) {
        const double t = std::fmod(static_cast<double>(i) / kRateHz, 0.5);
        const double hz = 60 + 90 * std::exp(-t / 0.03);
        music[i] =
            static_cast<float>(0.8 * std::exp(-t / 0.12) * std::sin(2 * std::numbers::pi * hz * t));
    }

    tactus::Engine engine;  // the default settings: the paper's section 6 mapping on each hit
    engine.set_actuators({{}, {.profile = {}, .gain_db = -6, .delay_ms = 5}});
    engine.enable_frame_queue();
    engine.prepare({.sample_rate_hz = kRateHz, .max_block = kBlock});

    std::atomic<bool> running = true;
    std::thread control([&] {  // a knob, turned back and forth
        for (int turn = 0; running; ++turn) {
            engine.set(tactus::P::envelope_decay_ms, turn % 2 ? 80.0 : 200.0);
            engine.set(tactus::P::post_drive_db, turn % 2 ? 0.0 : 3.0);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    });
    int onsets = 0, frames = 0;
    std::thread reader([&] {  // a GUI or an OSC sender
        tactus::AnalysisFrame frame;
        while (running || engine.pop_frame(frame)) {
            while (engine.pop_frame(frame)) {
                ++frames;
                onsets += frame.features.onset;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    });

    // The audio callback: any block size would do; this one is a device's, called here at ten
    // times a device's pace.
    std::vector<float> first(music.size()), second(music.size());
    auto next_block = std::chrono::steady_clock::now();
    for (size_t at = 0; at < music.size(); at += kBlock) {
        next_block += std::chrono::microseconds(static_cast<int>(1e6 * kBlock / kRateHz / 10));
        std::this_thread::sleep_until(next_block);
        const float* in[] = {music.data() + at};
        float* out[] = {first.data() + at, second.data() + at};
        engine.process(in, out, static_cast<int>(std::min<size_t>(kBlock, music.size() - at)));
    }
    running = false;
    control.join();
    reader.join();

    float peak[2] = {0, 0};
    for (size_t i = 0; i < music.size(); ++i) {
        peak[0] = std::max(peak[0], std::abs(first[i]));
        peak[1] = std::max(peak[1], std::abs(second[i]));
    }
    std::printf("latency %.1f ms; %d analysis frames, %d onsets (8 kicks); peaks %.3f and %.3f\n",
                1000.0 * engine.latency() / kRateHz, frames, onsets, peak[0], peak[1]);
    // The second output is 6 dB down: half the first's peak.
    return onsets >= 7 && peak[0] > 0.1f && peak[1] > 0.05f && peak[1] < peak[0] ? 0 : 1;
}
