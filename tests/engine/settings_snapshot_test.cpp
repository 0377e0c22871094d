// Engine::settings_snapshot() while control threads change the settings and the audio thread
// runs: every read is one whole Settings that was set (never a mix of two), versions only grow
// and name one set of values each, and a change the full queue refuses changes nothing. The
// tsan preset runs this file (make test-tsan): a data race on the settings fails it there.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <thread>
#include <vector>

#include "tactus/engine/engine.hpp"

namespace tactus {
namespace {

constexpr int kSets = 2000;

// The settings of step `k`: two live parameters that both say k, so a mix of two steps shows.
Settings step(int k) {
    Settings s;
    s.set(P::envelope_decay_ms, 100.0 + k);
    s.set(P::post_drive_db, -20.0 + 0.01 * k);
    return s;
}

// The step a snapshot's settings claim to be, or -1 when they are not a whole step.
int step_of(const Settings& s) {
    const int k = static_cast<int>(s[P::envelope_decay_ms]) - 100;
    if (s == Settings{}) return 0;
    return k >= 1 && k <= kSets && s == step(k) ? k : -1;
}

TEST(SettingsSnapshot, WholeAndVersionedWhileAnotherThreadSets) {
    Engine engine;
    engine.prepare(48000, 64);
    std::atomic<bool> stop{false};
    std::thread audio([&] {  // the audio thread takes the changes, as a device would
        std::vector<float> in(64, 0.01f), out(64);
        while (!stop.load(std::memory_order_relaxed)) engine.process(in.data(), out.data(), 64);
    });
    std::thread control([&] {
        for (int k = 1; k <= kSets; ++k)
            for (;;) {
                try {
                    engine.set(step(k));
                    break;
                } catch (const std::runtime_error&) {  // the queue is full: nothing changed
                    std::this_thread::yield();
                }
            }
    });

    uint64_t last_version = 0;
    int last_step = 0, reads = 0, torn = 0, backwards = 0, same_version_other_values = 0;
    while (last_step < kSets) {
        const SettingsSnapshot now = engine.settings_snapshot();
        const int k = step_of(now.settings);
        ++reads;
        if (k < 0) ++torn;
        if (now.version < last_version || k < last_step) ++backwards;
        if (now.version == last_version && k != last_step) ++same_version_other_values;
        last_version = now.version;
        last_step = k < 0 ? last_step : k;
    }
    control.join();
    stop = true;
    audio.join();

    EXPECT_EQ(torn, 0) << "of " << reads << " reads, these mixed two settings";
    EXPECT_EQ(backwards, 0);
    EXPECT_EQ(same_version_other_values, 0);
    EXPECT_EQ(engine.settings_snapshot().version, static_cast<uint64_t>(kSets))
        << "one version per change";
    EXPECT_TRUE(engine.settings() == step(kSets));
    engine.set(step(kSets));  // a value the engine already has changes nothing
    EXPECT_EQ(engine.settings_snapshot().version, static_cast<uint64_t>(kSets));
}

// With no audio thread taking them, changes fill the queue; the change that does not fit is
// refused whole: the settings and their version stay what the audio thread has.
TEST(SettingsSnapshot, AFullQueueChangesNothing) {
    Engine engine;
    engine.prepare(48000, 64);
    Settings next;
    bool refused = false;
    for (int k = 1; k <= Engine::kChangeCapacity && !refused; ++k) {
        next = step(k);  // two live changes each
        const SettingsSnapshot before = engine.settings_snapshot();
        try {
            engine.set(next);
        } catch (const std::runtime_error&) {
            refused = true;
            const SettingsSnapshot after = engine.settings_snapshot();
            EXPECT_TRUE(after.settings == before.settings) << "no part of the change applied";
            EXPECT_EQ(after.version, before.version);
            EXPECT_EQ(step_of(after.settings), k - 1);
        }
    }
    EXPECT_TRUE(refused) << "the queue never filled";
}

}  // namespace
}  // namespace tactus
