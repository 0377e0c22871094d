// The LV2 plugin in a real host (lv2_host.hpp, on lilv): at its defaults and at each of its
// presets it renders what `tactus render` renders, its latency port says the engine's latency,
// a control port changed between blocks goes through the engine's live path, and a state saved
// by lilv in one instance restores bit for bit in another; a layout the host sets (patch:Set of
// its path) plays as `tactus render --layout`, live, and comes back with the session, its delays
// included. (No program selection a host may make from its audio thread allocates or locks:
// lv2_realtime_test.cpp.)
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <thread>

#include "lv2_host.hpp"
#include "plugin_reference.hpp"
#include "support/run_cli.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/params/params.hpp"

namespace tactus::test {
namespace {

// Time the plugin's control thread gets to take a change to the engine (see the CLAP test).
constexpr auto kControlTime = std::chrono::milliseconds(1000);

std::string symbol(P id) {
    std::string s(spec(id).key);
    for (char& c : s)
        if (c == '.') c = '_';
    return s;
}

// Runs `sound` through an activated `instance` in kBlock blocks; before block a.block, the
// automation's control ports are set, read by a run of 0 frames, and given kControlTime.
Outputs play(Lv2Instance& instance, const Sound& sound,
             const std::vector<Automation>& automation = {}) {
    Outputs out(static_cast<size_t>(instance.output_channels()),
                std::vector<float>(sound.frames()));
    for (size_t start = 0, block = 0; start < sound.frames(); start += kBlock, ++block) {
        for (const Automation& a : automation)
            if (a.block == block) {
                for (const ParamChange& c : a.changes)
                    instance.control(symbol(*find_param(c.id))) = static_cast<float>(c.value);
                instance.run(nullptr, nullptr, 0);
                std::this_thread::sleep_for(kControlTime);
            }
        const auto n = static_cast<uint32_t>(std::min<size_t>(kBlock, sound.frames() - start));
        const float* in[2] = {sound.channels[0].data() + start, sound.channels[1].data() + start};
        std::vector<float*> o;
        for (auto& channel : out) o.push_back(channel.data() + start);
        instance.run(in, o.data(), n);
    }
    return out;
}

class Lv2Plugin : public Cli {
  protected:
    Sound render_cli(const std::string& options) {
        const auto out = dir_ / "reference.wav";
        EXPECT_EQ(run("render " + kDrums.string() + " -o " + out.string() + " --force " + options)
                      .exit_code,
                  0);
        return as_hosts_play(read_sound(out), drums_.frames());
    }
    Lv2World world_{TACTUS_PLUGIN_LV2};
    Sound drums_ = read_sound(kDrums);
};

TEST_F(Lv2Plugin, DefaultsRenderAsTheCommandLine) {
    const Sound cli = render_cli("");
    Lv2Instance instance(world_, drums_.sample_rate_hz, kBlock);
    ASSERT_EQ(instance.input_channels(), 2);
    ASSERT_EQ(instance.output_channels(), kActuators + 2);
    instance.activate();
    const Outputs out = play(instance, drums_);
    expect_each_actuator_is(out, kActuators, cli.channels[0], "LV2");
    Engine engine;
    engine.prepare({.sample_rate_hz = drums_.sample_rate_hz, .max_block = kBlock, .channels = 2});
    const auto latency = static_cast<size_t>(instance.control("lv2_latency"));
    std::printf("LV2 latency port: %zu samples\n", latency);
    EXPECT_EQ(latency, static_cast<size_t>(engine.latency()));
    for (size_t c = 0; c < 2; ++c)
        for (size_t i = latency; i < drums_.frames(); ++i)
            ASSERT_EQ(out[kActuators + c][i], drums_.channels[c][i - latency]) << i;
}

TEST_F(Lv2Plugin, EveryPresetIsAHostPresetRenderingAsTheCommandLine) {
    const auto presets = world_.presets();
    const auto files = list_presets();
    ASSERT_FALSE(files.empty());
    for (const PresetInfo& file : files) {
        ASSERT_TRUE(presets.count(file.name)) << file.name << " is not among the LV2 presets";
        const Sound cli = render_cli("--preset " + file.name);
        Lv2Instance instance(world_, drums_.sample_rate_hz, kBlock);
        instance.load_preset(presets.at(file.name));
        instance.activate();
        const double d = max_difference(play(instance, drums_)[0], cli.channels[0]);
        std::printf("LV2 preset %s vs tactus render --preset %s: largest difference %.3g\n",
                    file.name.c_str(), file.name.c_str(), d);
        EXPECT_LE(d, 1e-5);
    }
}

TEST_F(Lv2Plugin, ControlPortsGoThroughTheEnginesLivePath) {
    const Outputs unchanged = engine_reference(drums_, {});
    const double rate = drums_.sample_rate_hz;
    const std::vector<Automation> automation = {
        {block_before_peak(unchanged[0], rate, 0.2, 0.8), {{spec(P::envelope_decay_ms).id, 60.0}}},
        {block_before_peak(unchanged[0], rate, 1.0, 1.6), {{spec(P::onset_window_ms).id, 11.6}}}};
    Lv2Instance instance(world_, rate, kBlock);
    instance.activate();
    const Outputs out = play(instance, drums_, automation);
    const Outputs reference = engine_reference(drums_, automation);
    const double d = max_difference(out[0], reference[0]);
    std::printf("LV2 automated vs Engine::set at the same block: largest difference %.3g\n", d);
    EXPECT_LE(d, 1e-5);
    EXPECT_GT(max_difference(out[0], unchanged[0], automation[0].block * kBlock), 1e-2);
}

TEST_F(Lv2Plugin, StateSavedByTheHostRestoresBitForBit) {
    const double rate = drums_.sample_rate_hz;
    Outputs first;
    LilvState* state = nullptr;
    {
        Lv2Instance a(world_, rate, kBlock);
        a.control(symbol(P::frequency_out_max)) = 260;
        a.control(symbol(P::square_mix_curve)) = 0;
        a.control(symbol(P::loudness_window_ms)) = 20;
        a.activate();
        a.run(nullptr, nullptr, 0);  // the ports read
        std::this_thread::sleep_for(kControlTime);
        a.deactivate();
        a.activate();  // again: the engine prepared afresh with them
        first = play(a, drums_);
        state = a.save_state();
    }
    ASSERT_NE(state, nullptr);
    Lv2Instance b(world_, rate, kBlock);
    b.restore_state(state);
    lilv_state_free(state);
    EXPECT_EQ(b.control(symbol(P::frequency_out_max)), 260.0f);
    b.activate();
    const Outputs second = play(b, drums_);
    for (size_t c = 0; c < first.size(); ++c) EXPECT_EQ(first[c], second[c]) << "output " << c;
    Lv2Instance fresh(world_, rate, kBlock);
    fresh.activate();
    EXPECT_GT(max_difference(play(fresh, drums_)[0], first[0]), 1e-2);  // the state mattered
}

// The plugin's layout, a path property (DPF's state "layout", DISTRHO_PLUGIN_URI "#layout").
constexpr const char* kLayout = "urn:tactus:vibrotactile#layout";

TEST_F(Lv2Plugin, ALayoutTheHostSetsPlaysAsRenderWithItLive) {
    const auto layout = dir_ / "two.toml", seat = dir_ / "seat.toml";
    std::ofstream(layout) << two_part_layout();
    std::ofstream(seat) << "[[output]]\nroute = \"band:20-120\"\n";
    const Sound cli = render_cli("--layout " + layout.string());
    ASSERT_EQ(cli.channels.size(), 2u);
    Lv2Instance instance(world_, drums_.sample_rate_hz, kBlock);
    instance.activate();
    instance.set_path(kLayout, layout.string());  // swapped in while the engine runs
    const Outputs out = play(instance, drums_);
    // After the engine's 10 ms crossfade from the outputs it had, as if set from the start.
    const auto faded = static_cast<size_t>(0.02 * drums_.sample_rate_hz);
    for (size_t k = 0; k < 2; ++k) {
        const double d = max_difference(out[k], cli.channels[k], faded);
        std::printf("LV2 vibration %zu with a layout vs tactus render --layout: %.3g\n", k + 1, d);
        EXPECT_LE(d, 1e-5);
    }
    EXPECT_GT(max_difference(out[0], out[1]), 1e-2);  // each output its own part
    const auto again = [&] {                          // from the start, the layout kept
        instance.deactivate();
        instance.activate();
        return play(instance, drums_);
    };
    // A layout of more outputs than the plugin's ports, or of a channel its input lacks, is
    // refused: the last one plays on.
    instance.set_path(kLayout, (std::filesystem::path(TACTUS_LAYOUTS) / "column-4.toml").string());
    std::ofstream(dir_ / "third.toml") << "[[output]]\nroute = \"channel:3\"\n";
    instance.set_path(kLayout, (dir_ / "third.toml").string());
    const Outputs kept = again();
    for (size_t k = 0; k < 2; ++k) EXPECT_LE(max_difference(kept[k], cli.channels[k]), 1e-5);
    // One output: the second port is silent.
    instance.set_path(kLayout, seat.string());
    const Outputs one = again();
    EXPECT_GT(max_difference(one[0], std::vector<float>(drums_.frames())), 1e-2);
    EXPECT_EQ(one[1], std::vector<float>(drums_.frames()));
}

TEST_F(Lv2Plugin, ASessionsLayoutComesBackWithItsDelays) {
    const auto layout = dir_ / "late.toml";
    std::ofstream(layout) << two_part_layout(30);
    const Sound cli = render_cli("--layout " + layout.string());
    LilvState* state = nullptr;
    {
        Lv2Instance a(world_, drums_.sample_rate_hz, kBlock);
        a.activate();
        a.set_path(kLayout, layout.string());  // the delay waits for the next activation
        state = a.save_state();
    }
    ASSERT_NE(state, nullptr);
    Lv2Instance b(world_, drums_.sample_rate_hz, kBlock);
    b.restore_state(state);
    lilv_state_free(state);
    b.activate();
    const Outputs out = play(b, drums_);
    for (size_t k = 0; k < 2; ++k) {
        const double d = max_difference(out[k], cli.channels[k]);
        std::printf("LV2 vibration %zu, layout restored, vs tactus render --layout: %.3g\n", k + 1,
                    d);
        EXPECT_LE(d, 1e-5);
    }
}

}  // namespace
}  // namespace tactus::test
