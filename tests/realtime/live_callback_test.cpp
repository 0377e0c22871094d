// Real-time safety of `tactus live`'s audio callback (apps/tactus/live/live_callback.hpp): the
// callback runs block after block under the allocation and lock guard
// (support/allocation_counter.hpp) while, on their own threads as in `tactus live`, the OSC server
// receives real UDP traffic sent with liblo (every live parameter turned, a structural change,
// triggers, actuator trims, malformed and out-of-range messages), the preset watcher reloads a
// preset file rewritten on disk, the frame monitor reads frames and sends features over OSC, and
// --sync's delay moves (as `live` moves it when the settings change it). No allocation and no lock
// may happen inside the callback.
#include "live/live_callback.hpp"

#include <gtest/gtest.h>
#include <lo/lo.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "live/frame_monitor.hpp"
#include "live/live_control.hpp"
#include "live/osc_server.hpp"
#include "live/player.hpp"
#include "live/preset_watcher.hpp"
#include "support/allocation_counter.hpp"
#include "support/live_values.hpp"
#include "support/signals.hpp"
#include "support/sound_file.hpp"
#include "support/temp_dir.hpp"
#include "tactus/io/preset.hpp"

namespace tactus {
namespace {

using test::g_allocator_calls;
using test::g_mutex_locks;
using test::Guard;
using test::reset_counts;

constexpr double kRateHz = 48000;

class LiveCallbackRealTime : public test::TempDirTest {};

// Sends one message of every kind the address space has, and some it refuses.
void send_osc_traffic(lo_address to, size_t round, const std::vector<std::pair<P, double>>& turned,
                      const Settings& start) {
    const auto& [id, value] = turned[round % turned.size()];
    const std::string address = "/tactus/" + std::string(spec(id).key);
    const bool there = round / turned.size() % 2 == 0;
    if (!(spec(id).key.ends_with("weight") && (value == 0 || start[id] == 0)))
        lo_send(to, address.c_str(), "d", there ? value : start[id]);
    lo_send(to, "/tactus/actuator/2/gain", "f", -static_cast<float>(round % 12));
    if (round % 5 == 0) lo_send(to, "/tactus/trigger", "ff", 120.0f, 0.5f);
    if (round % 7 == 0) lo_send(to, "/tactus/trigger", "");
    if (round % 9 == 0) {  // refused: unknown, out of range, wrong type
        lo_send(to, "/tactus/no.such.key", "f", 1.0f);
        lo_send(to, "/tactus/post.drive_db", "f", 1e9f);
        lo_send(to, "/tactus/mapping.gate_db", "s", "loud");
    }
    if (round % 40 == 0)  // structural: a new pipeline primed and crossfaded in
        lo_send(to, "/tactus/analysis.hop_ms", "f", round % 80 == 0 ? 2.0f : 2.9f);
    if (round % 40 == 20) {  // routes and a layout: new pipelines too
        const char* routes[] = {"kick+snare", "band:40-200", "channel:2", "all"};
        lo_send(to, "/tactus/actuator/1/route", "s", routes[round / 40 % 4]);
    }
    if (round % 200 == 100) lo_send(to, "/tactus/layout", "s", "wrists");
}

TEST_F(LiveCallbackRealTime, PlayerWithOscTrafficAndPresetReloads) {
    // A stereo drum file, played to two sound channels (with --sync) and two actuators.
    const test::DrumSignal drums = test::drum_pattern(kRateHz, 10.0, 11);
    std::vector<float> stereo(2 * drums.audio.size());
    for (size_t i = 0; i < drums.audio.size(); ++i)
        stereo[2 * i] = stereo[2 * i + 1] = drums.audio[i];
    const auto file = dir_ / "drums.wav";
    ASSERT_NO_FATAL_FAILURE(test::write_sound_file(file, stereo, kRateHz, 2));
    const auto preset = dir_ / "live.toml";
    const auto write_preset = [&](double pitch_min_hz) {  // structural: a pipeline swap
        std::ofstream(dir_ / "next.toml") << "[pitch]\nmin_hz = " << pitch_min_hz << "\n";
        std::filesystem::rename(dir_ / "next.toml", preset);  // as editors save
    };
    write_preset(50);

    Settings start;
    apply_preset_file(start, preset);
    live::Player player({file}, kRateHz, /*loop=*/true);
    Engine engine(start);
    engine.set_actuators({ActuatorOutput{}, ActuatorOutput{.profile = {}, .gain_db = -3}});
    engine.enable_frame_queue();
    engine.prepare({.sample_rate_hz = kRateHz, .max_block = 256, .channels = 2});
    live::Routing routing{.device_inputs = 0,
                          .device_outputs = 5,
                          .actuator_channels = {0, 3},
                          .sound_channels = {1, 2}};
    live::LiveCallback callback(engine, &player, routing, /*sync_delay_samples=*/150);
    callback.begin();

    live::LiveControl control(engine, {});
    std::vector<std::string> refused;
    live::OscServer server({"127.0.0.1", 0}, control);
    lo_address to = lo_address_new("127.0.0.1", std::to_string(server.port()).c_str());
    lo_server listener = lo_server_new(nullptr, nullptr);  // where features go
    live::OscSender sender({"127.0.0.1", lo_server_get_port(listener)});
    live::FrameMonitor monitor(engine, &sender, 100);
    std::atomic<int> reloads{0};
    live::PresetWatcher watcher(preset, control, [&](const std::string&) { ++reloads; });
    server.start();

    const auto turned = test::turned_live_values(start);
    std::vector<float> out(5 * 512);
    float actuator_peak = 0;
    reset_counts();
    const int blocks = 3000;
    for (int b = 0; b < blocks; ++b) {
        const int frames = 16 + b % 497;
        if (b % 4 == 0) send_osc_traffic(to, static_cast<size_t>(b / 4), turned, start);
        if (b % 600 == 300) write_preset(51 + b / 600);
        if (b % 150 == 75) callback.set_sync_delay_samples(b % 300 == 75 ? 400 : 90);
        {
            Guard guard;
            callback.process(nullptr, out.data(), frames);
        }
        actuator_peak = std::max<float>(
            actuator_peak,
            static_cast<float>(test::peak({out.data(), static_cast<size_t>(frames)})));
        while (lo_server_recv_noblock(listener, 0) > 0) {
        }
        std::this_thread::sleep_for(std::chrono::microseconds(300));
    }
    EXPECT_EQ(g_allocator_calls.load(), 0) << "allocator calls inside the live callback";
    EXPECT_EQ(g_mutex_locks.load(), 0) << "mutex locks inside the live callback";
    EXPECT_GT(actuator_peak, 0.05) << "the callback must exercise the whole pipeline";
    EXPECT_GE(reloads.load(), 4) << "the preset file was rewritten 5 times";
    EXPECT_GT(monitor.onsets(), 10);
    EXPECT_GT(control.settings()[P::pitch_min_hz], 50.0) << "a reloaded preset applied";
    EXPECT_EQ(callback.sync_delay_samples(), 90) << "the sound's delay moved, back and forth";
    EXPECT_EQ(engine.outputs()[1].route.text(), "channel:2") << "the layout's right output";
    lo_address_free(to);
    lo_server_free(listener);
}

// An instrument's input (two device channels, downmixed) with parameters turned from a control
// thread while the callback runs.
TEST(LiveCallbackInput, ControlThreadChanges) {
    const std::vector<float> x = test::drum_pattern(kRateHz, 6.0, 5).audio;
    Engine engine;
    engine.set_actuators({ActuatorOutput{}});
    engine.prepare({.sample_rate_hz = kRateHz, .max_block = 64, .channels = 2});
    live::LiveCallback callback(
        engine, nullptr,
        {.device_inputs = 2, .device_outputs = 1, .actuator_channels = {0}, .sound_channels = {}},
        0);
    callback.begin();
    live::LiveControl control(engine, {});
    const auto turned = test::turned_live_values(Settings{});
    std::atomic<bool> done{false};
    std::thread turner([&] {
        for (size_t k = 0; !done; ++k) {
            const auto& [id, value] = turned[k % turned.size()];
            if (!spec(id).key.ends_with("weight"))
                control.set(id, k / turned.size() % 2 ? Settings{}[id] : value);
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    });
    std::vector<float> in(2 * 64), out(64);
    float peak = 0;
    reset_counts();
    for (size_t at = 0; at + 64 <= x.size(); at += 64) {
        std::copy(x.begin() + static_cast<long>(at), x.begin() + static_cast<long>(at + 64),
                  in.begin());
        std::copy(x.begin() + static_cast<long>(at), x.begin() + static_cast<long>(at + 64),
                  in.begin() + 64);
        {
            Guard guard;
            callback.process(in.data(), out.data(), 64);
        }
        peak = std::max<float>(peak, static_cast<float>(test::peak(out)));
        if (at % 6400 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    done = true;
    turner.join();
    EXPECT_EQ(g_allocator_calls.load(), 0);
    EXPECT_EQ(g_mutex_locks.load(), 0);
    EXPECT_GT(peak, 0.05);
    EXPECT_GT(callback.take_meters().input_peak, 0.0f);
}

}  // namespace
}  // namespace tactus
