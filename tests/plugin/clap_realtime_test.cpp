// Real-time safety of the plugin as a host runs it: the CLAP binary, loaded through clap_entry,
// processes drums while the host sends parameter events inside process() (live and structural
// parameters, choices, the bypass); this executable replaces the allocation functions and
// pthread_mutex_lock (support/allocation_counter.cpp) and counts the calls on the audio thread
// during process(): none may happen. The plugin's control thread, which takes the changes to
// Engine::set, allocates freely and is not counted. A sanity test shows the count reaches into
// the plugin's own code. Layouts loaded on another thread while audio runs: the same.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "clap_host.hpp"
#include "plugin_audio.hpp"
#include "support/allocation_counter.hpp"
#include "tactus/params/params.hpp"

namespace tactus::test {
namespace {

TEST(ClapRealtime, TheCountSeesThePluginsAllocations) {
    ClapLibrary library(TACTUS_PLUGIN_CLAP);
    reset_counts();
    {
        Guard guard;
        ClapInstance instance(library);  // DPF allocates the plugin and its ports
    }
    EXPECT_GT(g_allocator_calls.load(), 0);
}

TEST(ClapRealtime, ProcessWithParameterEventsNeitherAllocatesNorLocks) {
    ClapLibrary library(TACTUS_PLUGIN_CLAP);
    const Sound drums = read_sound(kDrums);
    ClapInstance instance(library);
    instance.activate(drums.sample_rate_hz, kBlock);
    const auto id = [](P p) { return spec(p).id; };
    // Every few blocks some events: live values, choices, structural values (a pipeline built
    // on the control thread, caught up and crossfaded in on the audio thread), the bypass.
    const std::vector<std::vector<ParamChange>> events = {
        {{id(P::frequency_out_max), 250.0, 0}, {id(P::envelope_decay_ms), 80.0, 17}},
        {{id(P::analysis_hop_ms), 4.0, 5}},
        {{id(P::amplitude_curve), 1.0, 0}, {id(P::post_drive_db), 6.0, 100}},
        {{0, 1.0, 3}},  // bypass on
        {{id(P::onset_window_ms), 11.6, 0}, {0, 0.0, 200}},
        {{id(P::post_flatten_strength), 0.5,
          0}},                                 // a flattening design fitted off the audio thread
        {{id(P::flutter_weight), 0.5, 0}},     // a component turned on: structural
        {{id(P::post_lookahead_ms), 3.0, 0}},  // the latency changes
    };
    reset_counts();
    long blocks = 0;
    for (int pass = 0; pass < 3; ++pass)
        for (size_t start = 0, block = 0; start < drums.frames(); start += kBlock, ++block) {
            const auto n = static_cast<uint32_t>(std::min<size_t>(kBlock, drums.frames() - start));
            const float* in[2] = {drums.channels[0].data() + start,
                                  drums.channels[1].data() + start};
            std::vector<std::vector<float>> out(4, std::vector<float>(n));
            float* o[4] = {out[0].data(), out[1].data(), out[2].data(), out[3].data()};
            const bool send = block % 40 == 10 && (block / 40) < events.size() && pass == 0;
            instance.stage(in, o, n, send ? events[block / 40] : std::vector<ParamChange>{});
            {
                Guard guard;
                instance.process_staged();
            }
            ++blocks;
            // Time for the control thread, so the changes reach the engine while audio runs.
            std::this_thread::sleep_for(std::chrono::milliseconds(send ? 60 : 1));
        }
    std::printf("%ld blocks of %u frames, %zu event blocks: %ld allocator calls, %ld locks\n",
                blocks, kBlock, events.size(), g_allocator_calls.load(), g_mutex_locks.load());
    EXPECT_EQ(g_allocator_calls.load(), 0) << "allocator calls inside the plugin's process()";
    EXPECT_EQ(g_mutex_locks.load(), 0) << "mutex locks inside the plugin's process()";
    EXPECT_TRUE(instance.restart_requested());  // the look-ahead moved the latency
}

TEST(ClapRealtime, LayoutsLoadedWhileAudioRunsNeitherAllocateNorLockInProcess) {
    ClapLibrary library(TACTUS_PLUGIN_CLAP);
    const Sound drums = read_sound(kDrums);
    const auto dir = std::filesystem::temp_directory_path() / "tactus_clap_realtime_layouts";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "two.toml") << two_part_layout();
    std::ofstream(dir / "one.toml") << "[[output]]\nroute = \"band:20-120\"\n";
    ClapInstance instance(library);
    instance.activate(drums.sample_rate_hz, kBlock);
    // The host's main thread loads sessions' layouts (routes, a profile, an overlay, a trim,
    // one output) while the audio thread processes: every engine change is built off it.
    std::atomic<bool> done{false};
    std::thread main_thread([&] {
        for (int i = 0; !done.load(); ++i) {
            instance.load_state(
                dpf_state((dir / (i % 2 ? "one.toml" : "two.toml")).string(), "layout"));
            std::this_thread::sleep_for(std::chrono::milliseconds(40));
        }
    });
    reset_counts();
    long blocks = 0, one = 0, both = 0;  // blocks with only the first port sounding, both
    for (int pass = 0; pass < 2; ++pass)
        for (size_t start = 0; start < drums.frames(); start += kBlock) {
            const auto n = static_cast<uint32_t>(std::min<size_t>(kBlock, drums.frames() - start));
            const float* in[2] = {drums.channels[0].data() + start,
                                  drums.channels[1].data() + start};
            std::vector<std::vector<float>> out(4, std::vector<float>(n));
            float* o[4] = {out[0].data(), out[1].data(), out[2].data(), out[3].data()};
            instance.stage(in, o, n, {});
            {
                Guard guard;
                instance.process_staged();
            }
            ++blocks;
            const auto sounds = [&](int k) {
                return std::any_of(out[k].begin(), out[k].end(), [](float x) { return x != 0; });
            };
            (sounds(1) ? both : one) += sounds(0) ? 1 : 0;
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    done = true;
    main_thread.join();
    std::filesystem::remove_all(dir);
    std::printf(
        "%ld blocks of %u frames, layouts loaded beside them: %ld allocator calls, "
        "%ld locks\n",
        blocks, kBlock, g_allocator_calls.load(), g_mutex_locks.load());
    EXPECT_EQ(g_allocator_calls.load(), 0) << "allocator calls inside the plugin's process()";
    EXPECT_EQ(g_mutex_locks.load(), 0) << "mutex locks inside the plugin's process()";
    EXPECT_GT(one, 0) << "the one-output layout was never heard";
    EXPECT_GT(both, 0) << "the two-output layout was never heard";
}

}  // namespace
}  // namespace tactus::test
