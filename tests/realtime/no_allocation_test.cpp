// Real-time safety of Engine::process(): this executable replaces every global allocation
// function and pthread_mutex_lock (support/allocation_counter.cpp), and counts the calls made
// while a thread-local guard is set. The guard is
// set only around process() calls on long, varied input (drum-like hits, silence, quiet passages,
// NaN/Inf/denormal samples, odd block sizes) at several sample rates: no allocation and no mutex
// lock may happen. Sanity tests prove the guard does see allocations and locks. The channel
// components (NPI flutter, NPIII pressure on a DC actuator: the four-channel preset) run too.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <pthread.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <mutex>
#include <new>
#include <optional>
#include <thread>
#include <vector>

#include "support/allocation_counter.hpp"
#include "support/live_values.hpp"
#include "support/signals.hpp"
#include "tactus/dsp/delay_line.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/perception/meter.hpp"

using tactus::test::escape;
using tactus::test::g_allocator_calls;
using tactus::test::g_mutex_locks;
using tactus::test::Guard;
using tactus::test::reset_counts;

namespace tactus {
namespace {

// The guard must be able to fail: these show it sees what the engine test looks for.
TEST(Guard, SeesVectorGrowth) {
    reset_counts();
    {
        Guard guard;
        std::vector<int> v;
        v.push_back(1);
        escape(v.data());
    }
    EXPECT_GT(g_allocator_calls.load(), 0);
}

TEST(Guard, SeesMallocAndAlignedNew) {
    reset_counts();
    {
        Guard guard;
        void* p = std::malloc(64);
        escape(p);
        std::free(p);
    }
    EXPECT_EQ(g_allocator_calls.load(), 2);
    reset_counts();
    {
        Guard guard;
        struct alignas(64) Wide {
            float x[16];
        };
        auto* w = new Wide;
        escape(w);
        delete w;
    }
    EXPECT_EQ(g_allocator_calls.load(), 2);
}

TEST(Guard, SeesMutexLocks) {
    std::mutex mutex;
    reset_counts();
    {
        Guard guard;
        mutex.lock();
        mutex.unlock();
    }
    EXPECT_EQ(g_mutex_locks.load(), 1);
    EXPECT_EQ(g_allocator_calls.load(), 0);
}

// The library's own allocations and locks are seen too: prepare() allocates (vectors, FFTW
// buffers) and takes the FFTW planner mutex.
TEST(Guard, SeesTheLibrarysAllocationsAndLocks) {
    Engine engine;
    reset_counts();
    {
        Guard guard;
        engine.prepare(48000, 512);
    }
    EXPECT_GT(g_allocator_calls.load(), 0);
    EXPECT_GT(g_mutex_locks.load(), 0);
}

TEST(Guard, CountsNothingOutsideTheGuard) {
    reset_counts();
    std::vector<int> v(1000, 1);
    escape(v.data());
    std::mutex mutex;
    mutex.lock();
    mutex.unlock();
    EXPECT_EQ(g_allocator_calls.load(), 0);
    EXPECT_EQ(g_mutex_locks.load(), 0);
}

// Long varied input: drum hits, digital silence, a quiet passage, NaN/Inf/denormal samples and
// an all-NaN stretch.
std::vector<float> varied_input(double fs) {
    test::DrumSignal drums = test::drum_pattern(fs, 12.0, 42);
    std::vector<float>& x = drums.audio;
    const float specials[] = {
        std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
        -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::denorm_min()};
    for (size_t i = 101, k = 0; i < x.size(); i += 4099, ++k) x[i] = specials[k % 4];
    for (size_t i = static_cast<size_t>(7 * fs); i < static_cast<size_t>(7.3 * fs); ++i)
        x[i] = std::numeric_limits<float>::quiet_NaN();
    const auto tone = test::sine(220.0, fs, static_cast<size_t>(fs), 0.5);
    std::copy(tone.begin(), tone.end(), x.begin() + static_cast<long>(9 * fs));
    return x;
}

void expect_process_is_real_time_safe(double fs, const Settings& settings,
                                      std::optional<ActuatorProfile> actuator = std::nullopt) {
    const std::vector<float> x = varied_input(fs);
    std::vector<float> y(x.size());
    Engine engine(settings);
    engine.set_actuator(std::move(actuator));
    engine.prepare(fs, Engine::kMaxBlock);  // may allocate: outside the guard
    const int sizes[] = {1, 7, 64, 480, 4096, 13, 1024, 139, 2};
    reset_counts();
    size_t done = 0;
    for (size_t b = 0; done < x.size(); ++b) {
        const int count = static_cast<int>(std::min<size_t>(x.size() - done, sizes[b % 9]));
        {
            Guard guard;
            engine.process(x.data() + done, y.data() + done, count);
        }
        done += static_cast<size_t>(count);
    }
    EXPECT_EQ(g_allocator_calls.load(), 0) << "allocator calls inside process() at " << fs << " Hz";
    EXPECT_EQ(g_mutex_locks.load(), 0) << "mutex locks inside process() at " << fs << " Hz";
    EXPECT_GT(test::peak(y), 0.05) << "the input must exercise the whole pipeline";
}

TEST(RealTime, EngineProcessNeitherAllocatesNorLocks) {
    expect_process_is_real_time_safe(48000, Settings{});
}

TEST(RealTime, AtOtherRatesAndSettings) {
    expect_process_is_real_time_safe(8000, Settings{});
    expect_process_is_real_time_safe(192000, Settings{});
    Settings s;
    s.set(P::envelope_sustain, 0.3);
    s.set(P::frequency_source, static_cast<double>(FeatureSource::pitch_hz));
    s.set(P::amplitude_smoothing_ms, 20);
    s.set(P::frequency_hold, 1);  // one frequency per pulse
    s.set(P::post_drive_db, 20);
    expect_process_is_real_time_safe(44100, s);
}

// The analysis resamples every input rate to 16 kHz: exact ratios of many phases, a whole ratio,
// and one approximated (Resampler::kMaxPhases).
TEST(RealTime, AtEveryKindOfAnalysisRatio) {
    for (const double fs : {22050.0, 37800.0, 44099.0, 96000.0})
        expect_process_is_real_time_safe(fs, Settings{});
}

TEST(RealTime, FourChannelComponents) {
    Settings s;
    apply_preset_file(s,
                      std::filesystem::path(TACTUS_SOURCE_DIR) / "presets" / "four-channel.toml");
    s.set(P::actuator_dc, 1);
    ASSERT_GT(s[P::flutter_weight], 0.0);
    ASSERT_GT(s[P::pressure_weight], 0.0);
    expect_process_is_real_time_safe(48000, s);
    expect_process_is_real_time_safe(8000, s);
    s.set(P::post_flutter_peak_db, 0);
    s.set(P::pressure_steps, 0);
    expect_process_is_real_time_safe(96000, s);
}

TEST(RealTime, WithActuatorCompensation) {
    for (const char* name : {"voice-coil", "lra-175", "erm"})
        expect_process_is_real_time_safe(48000, Settings{}, load_actuator(resolve_actuator(name)));
}

// Every live parameter turned while audio runs, an actuator's trim, triggers and a structural
// change now and then: the changes are set on another thread between blocks (Engine::set may
// allocate there: a flattening design, a new pipeline), and process() picks each up (catching a
// new pipeline up and crossfading to it) without an allocation, a free or a lock. Turning a
// component's weight from or to 0 is structural (routing): weights are turned only between values
// above 0. With several input channels their summed loudness is primed too. With an actuator
// profile each change goes through its fit (actuator/fit.hpp) on the control thread. With
// `routes`, the two outputs play routes of every kind (engine/route.hpp), swapped now and then.
void expect_live_changes_are_real_time_safe(const Settings& start, double fs, int channels,
                                            std::optional<ActuatorProfile> actuator = {},
                                            bool routes = false, bool own_profiles = false) {
    const std::vector<float> x = varied_input(fs);
    std::vector<float> y(x.size());
    Engine engine(start);
    // With own_profiles the second output has none: each plays its own fit, so a change the
    // fit moves is structural, and every 140 blocks the two swap profiles (set_outputs).
    const std::vector<ActuatorOutput> outputs = {
        ActuatorOutput{.profile = actuator},
        ActuatorOutput{.profile = own_profiles ? std::nullopt : actuator, .gain_db = -3}};
    std::vector<ActuatorOutput> swapped = outputs;
    std::swap(swapped[0].profile, swapped[1].profile);
    // With routes, every 140 blocks they swap between two sets of every kind (and an overlay).
    const auto routed = [&](const std::vector<std::pair<const char*, Overlay>>& each) {
        std::vector<ActuatorOutput> next = outputs;
        for (size_t k = 0; k < next.size(); ++k)
            next[k].route = Route::parse(each[k].first), next[k].overlay = each[k].second;
        return next;
    };
    const std::vector<ActuatorOutput> each_kind[] = {
        routed({{"kick+snare", {}}, {"channel:2", {}}}),
        routed({{"band:40-200", {{P::frequency_out_max, 90}}}, {"all", {}}})};
    engine.set_actuators(routes ? each_kind[0] : outputs);
    // A control thread's change of the outputs, their trims as set_actuator_gain_db left them.
    const auto set_outputs = [&](std::vector<ActuatorOutput> next) {
        for (size_t k = 0; k < next.size(); ++k) next[k].gain_db = engine.outputs()[k].gain_db;
        engine.set_outputs(next);
    };
    engine.enable_frame_queue();
    engine.prepare({.sample_rate_hz = fs, .max_block = 256, .channels = channels});
    std::vector<float> second(x.size());
    const auto changes = test::turned_live_values(start);
    reset_counts();
    size_t done = 0, change = 0;
    AnalysisFrame frame;
    for (size_t b = 0; done < x.size(); ++b) {
        const int count = static_cast<int>(std::min<size_t>(x.size() - done, 64 + b % 300));
        if (b % 7 == 0) {  // a control thread turns the next parameter back and forth
            std::thread control([&] {
                const auto& [id, value] = changes[change++ % changes.size()];
                if (spec(id).key.ends_with("weight") && (value == 0 || start[id] == 0)) return;
                engine.set(id, change / changes.size() % 2 ? start[id] : value);
                engine.set_actuator_gain_db(1, -static_cast<double>(b % 12));
                if (b % 35 == 0) engine.trigger(120, 0.5);
                if (b % 140 == 0)  // structural: a pipeline primed here, crossfaded in there
                    engine.set(P::analysis_hop_ms, b % 280 == 0 ? 2.0 : start[P::analysis_hop_ms]);
                if (routes && b % 140 == 70) set_outputs(each_kind[b % 280 == 70 ? 1 : 0]);
                if (own_profiles && b % 140 == 105) set_outputs(b % 280 == 105 ? swapped : outputs);
            });
            control.join();
        }
        {
            Guard guard;
            float* outs[] = {y.data() + done, second.data() + done};
            const float* in[] = {x.data() + done, x.data() + done};  // the same on each
            engine.process(in, outs, count);
        }
        while (engine.pop_frame(frame)) {
        }
        done += static_cast<size_t>(count);
    }
    EXPECT_GE(change, 2 * changes.size()) << "every live parameter turned there and back";
    EXPECT_EQ(g_allocator_calls.load(), 0) << "allocator calls inside process()";
    EXPECT_EQ(g_mutex_locks.load(), 0) << "mutex locks inside process()";
    EXPECT_GT(test::peak(y), 0.05) << "the input must exercise the whole pipeline";
}

TEST(RealTime, LiveParameterChanges) {
    expect_live_changes_are_real_time_safe(Settings{}, 48000, 1);
    Settings four;
    apply_preset_file(four,
                      std::filesystem::path(TACTUS_SOURCE_DIR) / "presets" / "four-channel.toml");
    four.set(P::actuator_dc, 1);
    expect_live_changes_are_real_time_safe(four, 44100, 2);
}

TEST(RealTime, RoutesOfEveryKindChangedLive) {
    expect_live_changes_are_real_time_safe(Settings{}, 48000, 2, {}, true);
}

TEST(RealTime, LiveParameterChangesFittedToAnActuator) {
    for (const char* name : {"lra-175", "erm"})
        expect_live_changes_are_real_time_safe(Settings{}, 48000, 1,
                                               load_actuator(resolve_actuator(name)));
}

TEST(RealTime, LiveChangesToOutputsOfTheirOwnProfiles) {
    expect_live_changes_are_real_time_safe(Settings{}, 48000, 1,
                                           load_actuator(resolve_actuator("lra-175")), false, true);
}

// The delay line of the pass-throughs (immediate moves) and of --sync (crossfaded moves): its
// process() and a delay that moves every few blocks, on odd block sizes, in place or not.
TEST(RealTime, DelayLineProcessAndDelayChanges) {
    const std::vector<float> x = varied_input(48000);  // 12 s
    for (const int fade_samples : {0, 480}) {
        DelayLine delay;
        delay.prepare(2, 1200, 300, fade_samples);
        std::vector<float> left(x.size()), right = x;
        reset_counts();
        int block = 0;
        for (size_t done = 0; done < x.size(); ++block) {
            const int count = static_cast<int>(std::min<size_t>(37 + block % 300, x.size() - done));
            Guard guard;
            if (block % 7 == 0) delay.set_delay_samples(block % 14 == 0 ? 1100 : 5);
            const float* in[] = {x.data() + done, right.data() + done};
            float* out[] = {left.data() + done, right.data() + done};
            delay.process(in, out, count);
            done += static_cast<size_t>(count);
        }
        EXPECT_EQ(g_allocator_calls.load(), 0) << "fade of " << fade_samples << " samples";
        EXPECT_EQ(g_mutex_locks.load(), 0) << "fade of " << fade_samples << " samples";
        EXPECT_EQ(std::memcmp(left.data(), right.data(), left.size() * sizeof(float)), 0)
            << "in place or not, the same (bit for bit: the input holds NaNs)";
    }
}

// The sensation meter is an offline tool, but after prepare() it does not allocate either.
TEST(RealTime, SensationMeterWriteNeitherAllocatesNorLocks) {
    const std::vector<float> x = varied_input(48000);
    perception::SensationMeter meter;
    meter.prepare(
        48000, [](double f) { return f > 0 ? 10.0 : 0.0; }, 2.9);
    int readings = 0;
    const std::function<void(const perception::MeterReading&)> count =
        [&](const perception::MeterReading&) { ++readings; };
    reset_counts();
    for (size_t done = 0; done < x.size(); done += 1000) {
        Guard guard;
        meter.write(x.data() + done, static_cast<int>(std::min<size_t>(1000, x.size() - done)),
                    count);
    }
    EXPECT_EQ(g_allocator_calls.load(), 0);
    EXPECT_EQ(g_mutex_locks.load(), 0);
    EXPECT_GT(readings, 1000);
}

}  // namespace
}  // namespace tactus
