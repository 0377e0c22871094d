// The CLAP plugin driven from a host's two threads at once, as a DAW drives it: the audio thread
// processes drums with parameter events in its blocks (live and structural values, the bypass)
// while the main thread saves the state, loads it back and reads parameter values. Beside them
// runs the plugin's own control thread, which takes the changes to the engine. Under
// ThreadSanitizer (make test-tsan) a race between any two of the three fails the test; in every
// build the output stays finite and within full scale, and every state saved loads again.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "clap_host.hpp"
#include "plugin_audio.hpp"
#include "tactus/params/params.hpp"

namespace tactus::test {
namespace {

TEST(ClapThreads, TheAudioThreadProcessesWhileTheMainThreadSavesAndLoadsState) {
    ClapLibrary library(TACTUS_PLUGIN_CLAP);
    const Sound drums = read_sound(kDrums);
    ClapInstance instance(library);
    instance.activate(drums.sample_rate_hz, kBlock);
    const auto id = [](P p) { return spec(p).id; };
    // Every 20 blocks one of these, in turn: live values, a structural one, the bypass.
    const std::vector<std::vector<ParamChange>> events = {
        {{id(P::frequency_out_max), 250.0, 0}, {id(P::envelope_decay_ms), 80.0, 17}},
        {{id(P::analysis_hop_ms), 4.0, 5}},
        {{0, 1.0, 3}},
        {{id(P::frequency_out_max), 180.0, 0}, {0, 0.0, 100}},
        {{id(P::analysis_hop_ms), 6.0, 0}},
    };

    std::atomic<bool> done{false};
    float largest = 0;
    bool finite = true;
    std::thread audio([&] {
        std::vector<std::vector<float>> out(4, std::vector<float>(kBlock));
        float* o[4] = {out[0].data(), out[1].data(), out[2].data(), out[3].data()};
        size_t block = 0;
        for (int pass = 0; pass < 2; ++pass)
            for (size_t start = 0; start < drums.frames(); start += kBlock, ++block) {
                const auto n =
                    static_cast<uint32_t>(std::min<size_t>(kBlock, drums.frames() - start));
                const float* in[2] = {drums.channels[0].data() + start,
                                      drums.channels[1].data() + start};
                instance.process(in, o, n,
                                 block % 20 == 10 ? events[(block / 20) % events.size()]
                                                  : std::vector<ParamChange>{});
                for (size_t c = 0; c < 2; ++c)
                    for (uint32_t i = 0; i < n; ++i) {
                        finite = finite && std::isfinite(out[c][i]);
                        largest = std::max(largest, std::abs(out[c][i]));
                    }
                // About real time (256 frames at 44.1 kHz: 5.8 ms), so the main thread's calls
                // fall between and during blocks.
                std::this_thread::sleep_for(std::chrono::milliseconds(2));
            }
        done = true;
    });
    int states = 0;
    while (!done) {
        const std::string state = instance.save_state();
        EXPECT_TRUE(instance.load_state(state)) << "state " << states;
        double value = 0;
        EXPECT_TRUE(
            instance.params().get_value(instance.plugin(), id(P::frequency_out_max), &value));
        ++states;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    audio.join();
    std::printf("%d states saved and loaded while the audio thread ran; largest output %.3f\n",
                states, largest);
    EXPECT_GT(states, 10);
    EXPECT_TRUE(finite);
    EXPECT_GT(largest, 0.05f);
    EXPECT_LE(largest, 1.0f);
}

}  // namespace
}  // namespace tactus::test
