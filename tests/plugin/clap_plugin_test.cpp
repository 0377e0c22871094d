// The CLAP plugin in a real host (clap_host.hpp: dlopen, clap_entry, the factory, process() in
// blocks): its parameters are the table's, its output at the defaults is `tactus render`'s, a
// change mid-file goes through the engine's live path, state restores bit for bit, a corrupt
// state gives the defaults, a session's layout plays as `render --layout`, the bypass ramps.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <thread>

#include "clap_host.hpp"
#include "plugin_audio.hpp"
#include "plugin_reference.hpp"
#include "support/run_cli.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/preset.hpp"

namespace tactus::test {
namespace {

// A host change reaches the engine through the plugin's control thread (within a
// millisecond; a structural one once its pipeline is built, about 25 ms here): this host gives
// it a second between blocks, room for a loaded machine, as a slow offline render does, so the
// block it starts at is known.
constexpr auto kControlTime = std::chrono::milliseconds(1000);

// Runs `sound` through `instance` (activated here) in kBlock blocks; `automation` is flushed
// between blocks, or sent as events in the block with `as_events`.
Outputs play(ClapInstance& instance, const Sound& sound,
             const std::vector<Automation>& automation = {}, bool as_events = false) {
    instance.activate(sound.sample_rate_hz, kBlock);
    Outputs out(static_cast<size_t>(instance.output_channels()),
                std::vector<float>(sound.frames()));
    for (size_t start = 0, block = 0; start < sound.frames(); start += kBlock, ++block) {
        const auto n = static_cast<uint32_t>(std::min<size_t>(kBlock, sound.frames() - start));
        std::vector<ParamChange> events;
        for (const Automation& a : automation)
            if (a.block == block) {
                if (as_events) {
                    events = a.changes;
                } else {
                    instance.flush(a.changes);
                    std::this_thread::sleep_for(kControlTime);
                }
            }
        const float* in[2] = {sound.channels[0].data() + start, sound.channels[1].data() + start};
        std::vector<float*> o;
        for (auto& channel : out) o.push_back(channel.data() + start);
        instance.process(in, o.data(), n, events);
    }
    return out;
}

class ClapPlugin : public Cli {
  protected:
    ClapLibrary library_{TACTUS_PLUGIN_CLAP};
    Sound drums_ = read_sound(kDrums);
};

TEST_F(ClapPlugin, ParametersAreTheTableByStableId) {
    ClapInstance instance(library_);
    const clap_plugin_params_t& params = instance.params();
    uint32_t largest = 0;
    for (const ParamSpec& s : param_table()) largest = std::max(largest, s.id);
    ASSERT_EQ(params.count(instance.plugin()), largest + 1);
    for (uint32_t i = 0; i <= largest; ++i) {
        clap_param_info_t info{};
        ASSERT_TRUE(params.get_info(instance.plugin(), i, &info));
        EXPECT_EQ(info.id, i);  // the id a session stores is the table's stable id
        if (i == 0) {
            EXPECT_TRUE(info.flags & CLAP_PARAM_IS_BYPASS);
            continue;
        }
        const ParamSpec& s = spec(*find_param(i));
        EXPECT_EQ(std::string(info.name), s.key);
        EXPECT_EQ(info.min_value, static_cast<float>(s.min)) << s.key;
        EXPECT_EQ(info.max_value, static_cast<float>(s.max)) << s.key;
        EXPECT_EQ(info.default_value, static_cast<float>(s.default_value)) << s.key;
        EXPECT_EQ(bool(info.flags & CLAP_PARAM_IS_STEPPED), s.type != ParamType::real) << s.key;
        EXPECT_TRUE(info.flags & CLAP_PARAM_IS_AUTOMATABLE) << s.key;
        if (!s.choices.empty() && s.type == ParamType::choice) {
            char text[64];
            ASSERT_TRUE(params.value_to_text(instance.plugin(), i, 1.0, text, sizeof text));
            EXPECT_EQ(std::string(text), s.choices[1]) << s.key;
        }
    }
}

TEST_F(ClapPlugin, DefaultsRenderAsTheCommandLine) {
    const auto reference = dir_ / "reference.wav";
    ASSERT_EQ(run("render " + kDrums.string() + " -o " + reference.string()).exit_code, 0);
    const Sound cli = as_hosts_play(read_sound(reference), drums_.frames());

    ClapInstance instance(library_);
    ASSERT_EQ(instance.input_channels(), 2);
    ASSERT_EQ(instance.output_channels(), kActuators + 2);
    const Outputs out = play(instance, drums_);
    expect_each_actuator_is(out, kActuators, cli.channels[0], "CLAP");
    // The latency the host is told is the engine's, and the music comes out delayed by it.
    Engine engine;
    engine.prepare({.sample_rate_hz = drums_.sample_rate_hz, .max_block = kBlock, .channels = 2});
    const uint32_t latency = instance.latency();
    std::printf("CLAP latency: %u samples\n", latency);
    EXPECT_EQ(latency, static_cast<uint32_t>(engine.latency()));
    EXPECT_GT(latency, 0u);
    for (size_t c = 0; c < 2; ++c)
        for (size_t i = latency; i < drums_.frames(); ++i)
            ASSERT_EQ(out[kActuators + c][i], drums_.channels[c][i - latency]) << i;
}

TEST_F(ClapPlugin, AutomationGoesThroughTheEnginesLivePath) {
    // A live parameter, then a structural one (a pipeline swapped in), each just before a hit.
    const Outputs unchanged = engine_reference(drums_, {});
    const double rate = drums_.sample_rate_hz;
    const uint32_t out_max = spec(P::frequency_out_max).id, hop = spec(P::analysis_hop_ms).id;
    const std::vector<Automation> automation = {
        {block_before_peak(unchanged[0], rate, 0.2, 0.8), {{out_max, 200.0}}},
        {block_before_peak(unchanged[0], rate, 1.0, 1.6), {{hop, 5.0}}}};
    ClapInstance instance(library_);
    const Outputs out = play(instance, drums_, automation);
    const Outputs reference = engine_reference(drums_, automation);
    const size_t from = automation[0].block * kBlock;
    const double d = max_difference(out[0], reference[0]);
    std::printf(
        "CLAP automated vs Engine::set at the same block: largest difference %.3g; "
        "vs no automation after it: %.3g\n",
        d, max_difference(out[0], unchanged[0], from));
    EXPECT_LE(d, 1e-5);
    EXPECT_EQ(max_difference(out[0], unchanged[0]), max_difference(out[0], unchanged[0], from));
    EXPECT_GT(max_difference(out[0], unchanged[0], from), 1e-2);  // the change is heard
    // No step beyond what the drums make anyway: the largest step in the 50 ms after each
    // change is no larger than the unchanged output's largest step anywhere, give or take the
    // 5 % a pulse's own level moves by when the analysis hop changes under it.
    constexpr double kPulseLevelChange = 1.05;
    const double own = kPulseLevelChange * max_step(unchanged[0], 0, drums_.frames());
    for (const Automation& a : automation) {
        const size_t at = a.block * kBlock;
        const double step =
            max_step(out[0], at, at + static_cast<size_t>(0.05 * drums_.sample_rate_hz));
        std::printf(
            "largest step after the change at %zu: %.4f (unchanged output's largest: %.4f)\n", at,
            step, own);
        EXPECT_LE(step, own);
    }
}

TEST_F(ClapPlugin, StateRestoresBitForBitInAnotherInstance) {
    const std::vector<ParamChange> changes = {{spec(P::frequency_out_max).id, 250.0},
                                              {spec(P::envelope_decay_ms).id, 90.0},
                                              {spec(P::amplitude_curve).id, 0.0},
                                              {spec(P::analysis_hop_ms).id, 4.0}};
    std::string state;
    Outputs first;
    {
        ClapInstance a(library_);
        a.flush(changes);  // before activation, as a host restoring a session's values
        first = play(a, drums_);
        state = a.save_state();
    }
    EXPECT_NE(state.find("out_max = 250.0"), std::string::npos);
    ClapInstance b(library_);
    ASSERT_TRUE(b.load_state(state));
    const Outputs second = play(b, drums_);
    for (size_t c = 0; c < first.size(); ++c)
        EXPECT_EQ(first[c], second[c]) << "output " << c;  // bit for bit
    ClapInstance fresh(library_);
    EXPECT_GT(max_difference(play(fresh, drums_)[0], first[0]), 1e-2);  // the state mattered
}

TEST_F(ClapPlugin, CorruptOrForeignStateGivesTheDefaults) {
    Settings changed;
    changed.set(P::frequency_out_max, 250);
    const std::string good = preset_text(changed, "state");
    ClapInstance fresh(library_);
    const Outputs defaults = play(fresh, drums_);
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string s = good;
        const size_t at = s.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return at == std::string::npos ? s : s.replace(at, from.size(), to);
    };
    // A newer format, a key of another program, text that is not TOML, a value out of range,
    // another plugin's blob, nothing.
    for (const std::string& bad :
         {dpf_state(replaced("format = 1", "format = 99")),
          dpf_state(replaced("out_max = 250.0", "volume_knob = 3")),
          dpf_state(replaced("[mapping]", "[[[\x01\x02")),
          dpf_state(replaced("out_max = 250.0", "out_max = 1e300")),
          std::string("{\"preset\": \"x\", \"gain\": 3}"), std::string()}) {
        ClapInstance c(library_);
        c.load_state(bad);
        double value = 0;
        ASSERT_TRUE(c.params().get_value(c.plugin(), spec(P::frequency_out_max).id, &value));
        EXPECT_EQ(value, static_cast<float>(spec(P::frequency_out_max).default_value));
        EXPECT_EQ(play(c, drums_), defaults);
    }
    // The good one in the same framing is taken.
    ClapInstance c(library_);
    ASSERT_TRUE(c.load_state(dpf_state(good)));
    double value = 0;
    ASSERT_TRUE(c.params().get_value(c.plugin(), spec(P::frequency_out_max).id, &value));
    EXPECT_EQ(value, 250.0);
}

TEST_F(ClapPlugin, ALayoutInASessionPlaysAsRenderWithIt) {
    const auto layout = dir_ / "two.toml", reference = dir_ / "reference.wav";
    std::ofstream(layout) << two_part_layout(30);
    ASSERT_EQ(run("render " + kDrums.string() + " -o " + reference.string() + " --layout " +
                  layout.string())
                  .exit_code,
              0);
    const Sound cli = as_hosts_play(read_sound(reference), drums_.frames());
    ClapInstance instance(library_);
    ASSERT_TRUE(instance.load_state(dpf_state(layout.string(), "layout")));
    const Outputs out = play(instance, drums_);
    for (size_t k = 0; k < 2; ++k) {
        const double d = max_difference(out[k], cli.channels[k]);
        std::printf("CLAP vibration %zu with a layout vs tactus render --layout: %.3g\n", k + 1, d);
        EXPECT_LE(d, 1e-5);
    }
    EXPECT_NE(instance.save_state().find(layout.string()), std::string::npos);  // saved again
}

TEST_F(ClapPlugin, BypassRampsInsteadOfClicking) {
    const Outputs on = engine_reference(drums_, {});
    const size_t block = block_before_peak(on[0], drums_.sample_rate_hz, 0.2, 0.8) + 2;
    ClapInstance instance(library_);
    const Outputs out = play(instance, drums_, {{block, {{0, 1.0}}}}, /*as_events=*/true);
    const size_t at = block * kBlock;
    const auto ramp = static_cast<size_t>(0.020 * drums_.sample_rate_hz);
    EXPECT_EQ(max_difference(std::vector<float>(out[0].begin(), out[0].begin() + at),
                             std::vector<float>(on[0].begin(), on[0].begin() + at)),
              0.0);
    EXPECT_GT(max_difference(out[0], on[0], at), 0.0);
    for (size_t i = at + ramp + 1; i < drums_.frames(); ++i) ASSERT_EQ(out[0][i], 0.0f) << i;
    const double step = max_step(out[0], at, at + ramp + 2);
    std::printf("bypass: largest step in the ramp %.4f, the running output's largest %.4f\n", step,
                max_step(on[0], 0, drums_.frames()));
    EXPECT_LE(step, max_step(on[0], 0, drums_.frames()));
    // The music goes on through the bypass.
    for (size_t i = at; i < drums_.frames(); ++i)
        ASSERT_EQ(out[kActuators][i], drums_.channels[0][i - instance.latency()]);
}

}  // namespace
}  // namespace tactus::test
