// What front ends ask of the Engine beyond the offline render: blocks of any size (0, 1, above
// max_block, changing call to call) give the output of fixed blocks bit for bit; input channels
// are downmixed in the engine (mean or a chosen channel); N actuator outputs share one analysis,
// each with its own profile, trim and delay; live parameters turned while audio runs glide (no
// step in the output larger than the unturned outputs have) and a turn to the current value
// changes nothing; a structural change while running is primed and crossfaded in (no lost
// onset, no gap, no larger step, the hop grid and the summed loudness kept; a preset's changes
// at once end as each in turn); the vibration program can be injected (triggers from outside)
// and read (frames through a queue).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "support/engine_blocks.hpp"
#include "support/live_values.hpp"
#include "support/signals.hpp"
#include "tactus/actuator/fit.hpp"
#include "tactus/core/units.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/preset.hpp"

namespace tactus {
namespace {

using ::testing::HasSubstr;

Settings four_channel() {
    Settings s;
    apply_preset_file(s,
                      std::filesystem::path(TACTUS_SOURCE_DIR) / "presets" / "four-channel.toml");
    s.set(P::actuator_dc, 1);
    return s;
}

// Runs the engine over `in` (one vector per input channel) in blocks cycling through `blocks`;
// one output vector per actuator.
std::vector<std::vector<float>> run(Engine& engine, const std::vector<std::vector<float>>& in,
                                    const std::vector<int>& blocks) {
    const size_t n = in.front().size();
    std::vector<std::vector<float>> out(static_cast<size_t>(engine.actuators()),
                                        std::vector<float>(n));
    std::vector<const float*> ins(in.size());
    std::vector<float*> outs(out.size());
    size_t done = 0;
    for (size_t b = 0; done < n || b < blocks.size(); ++b) {
        const int count = static_cast<int>(
            std::min<size_t>(n - done, static_cast<size_t>(blocks[b % blocks.size()])));
        for (size_t c = 0; c < in.size(); ++c) ins[c] = in[c].data() + done;
        for (size_t k = 0; k < out.size(); ++k) outs[k] = out[k].data() + done;
        engine.process(ins.data(), outs.data(), count);
        done += static_cast<size_t>(count);
    }
    return out;
}

std::vector<float> mono_render(const std::vector<float>& x, double fs, const Settings& s = {},
                               std::optional<ActuatorProfile> actuator = std::nullopt) {
    Engine engine(s);
    engine.set_actuator(std::move(actuator));
    engine.prepare(fs, 64);
    return test::process_in_blocks(engine, x, 64);
}

TEST(EngineFrontEnd, AnyBlockSizeGivesTheOutputOfFixedBlocks) {
    const double fs = 48000;
    const std::vector<float> x = test::drum_pattern(fs, 3.0, 3).audio;
    for (const Settings& s : {Settings{}, four_channel()}) {
        const std::vector<float> reference = mono_render(x, fs, s);
        ASSERT_GT(test::peak(reference), 0.05);
        for (const std::vector<int>& blocks :
             {std::vector<int>{1024}, {0, 1, 0, 4096, 63, 65, 5000, 1}, {17, 0, 300, 8192}}) {
            Engine engine(s);
            engine.prepare(fs, 64);  // every block above is split inside process()
            const auto y = run(engine, {x}, blocks);
            EXPECT_TRUE(test::same_bits(y[0], reference)) << "blocks from " << blocks.front();
        }
    }
}

// The analysis frames of `in` (one vector per channel) through an engine in 64-frame blocks.
std::vector<AnalysisFrame> frames_of(const std::vector<std::vector<float>>& in, double fs) {
    Engine engine;
    engine.enable_frame_queue();
    engine.prepare(
        {.sample_rate_hz = fs, .max_block = 64, .channels = static_cast<int>(in.size())});
    run(engine, in, {64});
    std::vector<AnalysisFrame> frames;
    for (AnalysisFrame f; engine.pop_frame(f);) frames.push_back(f);
    return frames;
}

// Several channels are analysed as their mean, except the loudness, which is their sum as
// ITU-R BS.1770 sums it: the same signal on two channels is 3.01 dB louder than on one, one
// channel beside silence as loud as alone (its mean would read 6.02 dB quieter).
TEST(EngineFrontEnd, ChannelsAreDownmixedInTheEngineAndTheirLoudnessSummed) {
    const double fs = 44100;
    const auto left = test::drum_pattern(fs, 2.0, 5).audio;
    const auto right = test::drum_pattern(fs, 2.0, 6).audio;
    const std::vector<float> silence(left.size(), 0.0f);
    std::vector<float> mean(left.size());
    for (size_t i = 0; i < mean.size(); ++i) mean[i] = (left[i] + right[i]) * 0.5f;

    const auto stereo = frames_of({left, right}, fs), mixed = frames_of({mean}, fs);
    ASSERT_EQ(stereo.size(), mixed.size());
    int onsets = 0;
    for (size_t f = 0; f < stereo.size(); ++f) {
        EXPECT_EQ(stereo[f].features.onset, mixed[f].features.onset) << f;
        EXPECT_EQ(stereo[f].features.brightness_hz, mixed[f].features.brightness_hz) << f;
        onsets += stereo[f].features.onset;
    }
    EXPECT_GT(onsets, 3);

    const auto alone = frames_of({left}, fs), twice = frames_of({left, left}, fs),
               beside_silence = frames_of({left, silence}, fs);
    ASSERT_EQ(alone.size(), twice.size());
    int loud_frames = 0;
    for (size_t f = 0; f < alone.size(); ++f) {
        const double db = alone[f].features.loudness_db;
        if (db < -100) continue;
        ++loud_frames;
        EXPECT_NEAR(twice[f].features.loudness_db, db + 10 * std::log10(2.0), 1e-3) << f;
        EXPECT_NEAR(beside_silence[f].features.loudness_db, db, 1e-3) << f;
    }
    EXPECT_GT(loud_frames, 100);

    Engine chosen;  // one channel analysed: exactly as if it came alone
    chosen.set_input_channel(1);
    chosen.prepare({.sample_rate_hz = fs, .max_block = 64, .channels = 2});
    EXPECT_TRUE(test::same_bits(run(chosen, {left, right}, {64})[0], mono_render(right, fs)));
    Engine bad;
    bad.set_input_channel(2);
    EXPECT_THROW(bad.prepare({.sample_rate_hz = fs, .channels = 2}), std::invalid_argument);
}

// The analysis is shared; each output plays the settings fitted to its own profile
// (actuator/fit.hpp) with its own compensation, trim and delay.
TEST(EngineFrontEnd, ActuatorsShareOneAnalysisWithTheirOwnProfileTrimAndDelay) {
    const double fs = 48000;
    const auto x = test::drum_pattern(fs, 2.0, 7).audio;
    const ActuatorProfile lra = load_actuator(resolve_actuator("lra-175"));
    Engine engine;
    engine.set_actuators({ActuatorOutput{.profile = lra, .gain_db = 0, .delay_ms = 0},
                          ActuatorOutput{},
                          ActuatorOutput{.profile = {}, .gain_db = -6, .delay_ms = 10}});
    engine.prepare(fs, 64);
    const auto y = run(engine, {x}, {64});
    const auto compensated = mono_render(x, fs, {}, lra);
    const auto plain = mono_render(x, fs);
    EXPECT_TRUE(test::same_bits(y[0], compensated));
    // Each output plays its own profile's fit: none, the default mapping, not the LRA's.
    EXPECT_TRUE(test::same_bits(y[1], plain));
    EXPECT_FALSE(test::same_bits(y[1], mono_render(x, fs, fit_to_actuator(lra, {}).settings)));
    const size_t delay = 480;  // 10 ms
    for (size_t i = 0; i < delay; ++i) ASSERT_EQ(y[2][i], 0.0f);
    for (size_t i = delay; i < x.size(); ++i)
        ASSERT_EQ(y[2][i], static_cast<float>(plain[i - delay] * db_to_gain(-6))) << i;
    EXPECT_THROW(engine.set_actuators({ActuatorOutput{.profile = {}, .gain_db = 3}}),
                 std::invalid_argument);
}

// The largest step between neighbouring samples in [begin, end): a click is a step far larger
// than the signal's own slope there.
double largest_step(const std::vector<float>& y, size_t begin, size_t end) {
    double step = 0;
    for (size_t i = std::max<size_t>(begin, 1); i < std::min(end, y.size()); ++i)
        step = std::max(step, double{std::fabs(y[i] - y[i - 1])});
    return step;
}

// Each live parameter turned every 0.27 s, there and back, while drums play: around each turn
// the output steps no more than the outputs with either value held throughout step there.
TEST(EngineFrontEnd, LiveChangesGlideWithoutAStep) {
    const double fs = 48000;
    constexpr int kBlock = 64, kEvery = 200;  // blocks between turns
    const auto x = test::drum_pattern(fs, 2.0, 9).audio;
    for (const Settings& start : {Settings{}, four_channel()}) {
        for (const auto& [id, value] : test::turned_live_values(start)) {
            if (spec(id).key.ends_with("weight") && (value == 0 || start[id] == 0)) continue;
            Settings turned = start;
            turned.set(id, value);
            const auto held = mono_render(x, fs, start), held_turned = mono_render(x, fs, turned);
            Engine engine(start);
            engine.prepare(fs, kBlock);
            std::vector<float> y(x.size());
            std::vector<size_t> turns;
            for (size_t done = 0, b = 0; done < x.size(); done += kBlock, ++b) {
                if (b % kEvery == kEvery / 2) {
                    engine.set(id, b % (2 * kEvery) == kEvery / 2 ? value : start[id]);
                    turns.push_back(done);
                }
                engine.process(x.data() + done, y.data() + done, kBlock);
            }
            const auto window = static_cast<size_t>(0.02 * fs);  // the turn and its glide
            for (size_t t : turns) {
                const double allowed = 1.5 * std::max(largest_step(held, t, t + window),
                                                      largest_step(held_turned, t, t + window));
                EXPECT_LE(largest_step(y, t, t + window), allowed + 1e-4)
                    << spec(id).key << " " << start[id] << " <-> " << value << " at " << t;
            }
        }
    }
}

TEST(EngineFrontEnd, TurningAParameterToItsValueChangesNothing) {
    const double fs = 48000;
    const auto x = test::drum_pattern(fs, 2.0, 4).audio;
    const Settings start = four_channel();
    const auto reference = mono_render(x, fs, start);
    Engine engine(start);
    engine.prepare(fs, 64);
    std::vector<float> y(x.size());
    std::vector<P> live;
    for (const ParamSpec& s : param_table())
        if (s.change == ParamChange::live) live.push_back(s.param);
    // One parameter per block, round robin (a flattening design takes milliseconds to fit).
    for (size_t done = 0, turn = 0; done < x.size(); done += 64, ++turn) {
        const P id = live[turn % live.size()];
        engine.set(id, start[id]);
        engine.process(x.data() + done, y.data() + done, 64);
    }
    EXPECT_TRUE(test::same_bits(y, reference));
}

TEST(EngineFrontEnd, ValuesAreCheckedBeforeAnythingChanges) {
    Engine engine;
    engine.prepare(48000, 64);
    try {
        engine.set(P::post_drive_db, 99);
        ADD_FAILURE() << "accepted an out-of-range value";
    } catch (const std::invalid_argument& e) {
        EXPECT_THAT(e.what(), HasSubstr("post.drive_db"));
    }
    EXPECT_EQ(engine.settings()[P::post_drive_db], Settings{}[P::post_drive_db]);
    EXPECT_THROW(engine.set_actuator_gain_db(0, 1), std::invalid_argument);
    EXPECT_THROW(engine.set_actuator_gain_db(1, -1), std::invalid_argument);
}

// Onset times the observer sees.
struct OnsetLog : FrameObserver {
    std::vector<int64_t> onsets;
    void on_frame(const Features& f, const ControlFrame&) noexcept override {
        if (f.onset) onsets.push_back(f.onset_sample);
    }
};

// A pipeline swapped in for a structural change is primed with the channels' summed loudness
// too: before, during and after the change the loudness reads as in an engine that always
// had the new setting.
TEST(EngineFrontEnd, StructuralChangesKeepTheSummedLoudnessOfSeveralChannels) {
    const double fs = 48000;
    const auto left = test::drum_pattern(fs, 3.0, 12).audio;
    const auto right = test::drum_pattern(fs, 3.0, 13).audio;
    Settings after;
    after.set(P::onset_window_ms, 8.0);  // keeps the hop: frames line up
    const auto loudness_of = [&](Engine& engine, bool change) {
        engine.enable_frame_queue();
        engine.prepare({.sample_rate_hz = fs, .max_block = 64, .channels = 2});
        std::vector<double> db;
        for (size_t done = 0; done + 64 <= left.size(); done += 64) {
            if (change && done == static_cast<size_t>(1.5 * fs))
                engine.set(P::onset_window_ms, 8.0);
            const float* in[] = {left.data() + done, right.data() + done};
            float out[64];
            float* outs[] = {out};
            engine.process(in, outs, 64);
            for (AnalysisFrame f; engine.pop_frame(f);) db.push_back(f.features.loudness_db);
        }
        return db;
    };
    Engine changed, held(after);
    const auto y = loudness_of(changed, true), reference = loudness_of(held, false);
    ASSERT_EQ(y.size(), reference.size());
    int compared = 0;
    for (size_t f = 0; f < y.size(); ++f, ++compared)
        EXPECT_NEAR(y[f], reference[f], 1e-3) << "frame " << f;
    EXPECT_GT(compared, 100);
}

// Structural changes while drums play (the hop, the onset window, the look-ahead, the flutter
// turned on): the new pipeline is primed and crossfaded in. Every hit the unchanged engine finds
// is found within 10 ms; around each change the output never drops out and steps no more than
// the outputs with the settings before or after it held throughout.
TEST(EngineFrontEnd, StructuralChangesLoseNoOnsetAndLeaveNoGap) {
    const double fs = 48000;
    constexpr int kBlock = 64;
    const auto drums = test::drum_pattern(fs, 8.0, 11);
    const std::vector<float>& x = drums.audio;
    const std::vector<std::pair<double, std::pair<P, double>>> changes = {
        {1.5, {P::analysis_hop_ms, 2.0}},
        {3.0, {P::onset_window_ms, 8.0}},
        {4.5, {P::post_lookahead_ms, 2 * Settings{}[P::post_lookahead_ms]}},
        {6.0, {P::flutter_weight, 0.3}}};
    // references[k]: the settings after k changes, held throughout.
    std::vector<std::vector<float>> references;
    Settings held_settings;
    OnsetLog held_log;
    for (size_t k = 0; k <= changes.size(); ++k) {
        if (k > 0) held_settings.set(changes[k - 1].second.first, changes[k - 1].second.second);
        Engine held(held_settings);
        if (k == 0) held.set_observer(&held_log);
        held.prepare(fs, kBlock);
        references.push_back(test::process_in_blocks(held, x, kBlock));
    }
    OnsetLog changed_log;
    Engine engine;
    engine.set_observer(&changed_log);
    engine.prepare(fs, kBlock);
    const int latency_before = engine.latency();
    std::vector<float> y(x.size());
    std::vector<size_t> at;
    for (size_t done = 0; done < x.size(); done += kBlock) {
        if (at.size() < changes.size() && done >= changes[at.size()].first * fs) {
            engine.set(changes[at.size()].second.first, changes[at.size()].second.second);
            at.push_back(done);
        }
        engine.process(x.data() + done, y.data() + done, kBlock);
    }
    ASSERT_EQ(at.size(), changes.size());
    EXPECT_EQ(engine.hop_samples(), 96) << "2 ms at 48 kHz";
    // Twice the default look-ahead, each rounded to the internal rate (a divisor of 4 at 48 kHz).
    EXPECT_NEAR(engine.latency(), 2 * latency_before, engine.rate_divisor())
        << "twice the default look-ahead";

    ASSERT_GE(held_log.onsets.size(), 20u);
    const auto tolerance = static_cast<int64_t>(0.01 * fs);
    for (int64_t onset : held_log.onsets) {
        const bool found = std::any_of(changed_log.onsets.begin(), changed_log.onsets.end(),
                                       [&](int64_t o) { return std::abs(o - onset) <= tolerance; });
        EXPECT_TRUE(found) << "the hit at " << onset / fs << " s is lost";
    }
    EXPECT_LE(changed_log.onsets.size(), held_log.onsets.size() + 2) << "no false hits";

    const auto window = static_cast<size_t>(0.005 * fs);
    for (size_t k = 0; k < at.size(); ++k) {
        const auto& before = references[k];
        const auto& after = references[k + 1];
        const size_t t = at[k];
        for (size_t w = t - 10 * window; w < t + 20 * window; w += window) {
            const double expected = std::min(test::peak(std::span(before).subspan(w, window)),
                                             test::peak(std::span(after).subspan(w, window)));
            if (expected > 0.02) {
                EXPECT_GT(test::peak(std::span(y).subspan(w, window)), 0.3 * expected)
                    << "a gap at " << w / fs << " s";
            }
        }
        EXPECT_LE(largest_step(y, t, t + 20 * window),
                  1.5 * std::max(largest_step(before, t, t + 20 * window),
                                 largest_step(after, t, t + 20 * window)) +
                      1e-3)
            << "a step at " << t / fs << " s";
    }
}

// A preset or a restored state arrives as a whole (Engine::set(const Settings&)): its live
// values act at the same block as one set() each, bit for bit, and its structural ones end in
// the same vibration as one set() each once the new pipeline has taken over.
TEST(EngineFrontEnd, SettingsAtOnceActAsEachValueInTurn) {
    const double fs = 44100;
    constexpr int kBlock = 128;
    const auto drums = test::drum_pattern(fs, 5.0, 3);
    const std::vector<float>& x = drums.audio;
    const size_t change_at = static_cast<size_t>(2.0 * fs) / kBlock * kBlock;
    const auto render = [&](const Settings& target, bool at_once) {
        Engine engine;
        engine.prepare(fs, kBlock);
        std::vector<float> y(x.size());
        for (size_t done = 0; done < x.size(); done += kBlock) {
            if (done == change_at) {
                if (at_once) {
                    engine.set(target);
                } else {
                    for (const ParamSpec& s : param_table())
                        if (target[s.param] != engine.settings()[s.param])
                            engine.set(s.param, target[s.param]);
                }
                EXPECT_TRUE(engine.settings() == target);
            }
            const size_t n = std::min<size_t>(kBlock, x.size() - done);
            engine.process(x.data() + done, y.data() + done, static_cast<int>(n));
        }
        return y;
    };
    Settings live;
    live.set(P::envelope_decay_ms, 60);
    live.set(P::frequency_out_max, 300);
    live.set(P::post_flatten_strength, 0.5);
    EXPECT_EQ(render(live, true), render(live, false));

    Settings structural = live;
    structural.set(P::onset_window_ms, 8);
    structural.set(P::post_lookahead_ms, 3);
    const std::vector<float> at_once = render(structural, true),
                             in_turn = render(structural, false);
    const auto settled = static_cast<std::ptrdiff_t>(change_at + 0.1 * fs);
    ASSERT_GT(test::peak(std::span(in_turn).subspan(static_cast<size_t>(settled))), 0.05);
    EXPECT_TRUE(std::equal(at_once.begin() + settled, at_once.end(), in_turn.begin() + settled));
}

// A structural change long after the start (more than the priming input) that keeps the hop:
// the new pipeline's frames end where the running one's would, so the analysis goes on as if
// nothing had changed (frames off that grid find other onsets on real drums).
struct FrameLog : FrameObserver {
    std::vector<int64_t> ends, onsets;
    void on_frame(const Features& f, const ControlFrame&) noexcept override {
        ends.push_back(f.frame_end_sample);
        if (f.onset) onsets.push_back(f.onset_sample);
    }
};

TEST(EngineFrontEnd, StructuralChangesLateInAFileKeepTheHopGrid) {
    const double fs = 44100;
    constexpr int kBlock = 64;
    const auto x = test::drum_pattern(fs, 8.0, 14).audio;
    FrameLog held_log, changed_log;
    Engine held;
    held.set_observer(&held_log);
    held.prepare(fs, kBlock);
    test::process_in_blocks(held, x, kBlock);
    Engine engine;
    engine.set_observer(&changed_log);
    engine.prepare(fs, kBlock);
    std::vector<float> y(x.size());
    const auto change_at = static_cast<size_t>(5.0 * fs) / kBlock * kBlock;  // after 2.5 s
    test::process_in_blocks(engine, x.data(), y.data(), change_at, {kBlock});
    engine.set(P::post_lookahead_ms, 3.0);
    test::process_in_blocks(engine, x.data() + change_at, y.data() + change_at,
                            x.size() - change_at, {kBlock});
    ASSERT_GE(held_log.onsets.size(), 20u);
    EXPECT_EQ(changed_log.ends, held_log.ends);
    EXPECT_EQ(changed_log.onsets, held_log.onsets);
}

// A new pipeline hears as much input as its stages remember (Engine::prime_seconds: 0.56 s at
// the defaults, where the limiter's release is the longest memory; longer memories more, up to
// kPrimeSeconds): once the crossfade is over it plays as an engine that had the new settings
// from the start, sample for sample within 60 dB of the output's peak.
TEST(EngineFrontEnd, APrimedPipelinePlaysAsOneThatRanFromTheStart) {
    const double fs = 48000;
    constexpr int kBlock = 64;
    const auto x = test::drum_pattern(fs, 7.0, 15).audio;
    Settings after;
    after.set(P::onset_window_ms, 8.0);  // keeps the hop: frames line up
    EXPECT_NEAR(Engine::prime_seconds(after), 0.56, 0.01);
    Engine held(after);
    held.prepare(fs, kBlock);
    const auto reference = test::process_in_blocks(held, x, kBlock);
    Engine engine;
    engine.prepare(fs, kBlock);
    std::vector<float> y(x.size());
    const auto change_at = static_cast<size_t>(4.0 * fs) / kBlock * kBlock;
    test::process_in_blocks(engine, x.data(), y.data(), change_at, {kBlock});
    engine.set(P::onset_window_ms, 8.0);
    test::process_in_blocks(engine, x.data() + change_at, y.data() + change_at,
                            x.size() - change_at, {kBlock});
    const auto settled = change_at + static_cast<size_t>(0.05 * fs);
    const double peak = test::peak(std::span(reference).subspan(settled));
    ASSERT_GT(peak, 0.05);
    double largest = 0;
    for (size_t i = settled; i < x.size(); ++i)
        largest = std::max(largest, std::abs(double(y[i]) - reference[i]));
    EXPECT_LT(largest, 1e-3 * peak) << 20 * std::log10(largest / peak) << " dB re the peak";

    Settings long_memory = after;
    long_memory.set(P::envelope_decay_ms, 1200);
    EXPECT_NEAR(Engine::prime_seconds(long_memory), 1.21, 0.01) << "the decay's 60 dB";
    long_memory.set(P::onset_history_ms, 2000);
    long_memory.set(P::post_release_ms, 2000);
    EXPECT_EQ(Engine::prime_seconds(long_memory), Engine::kPrimeSeconds);
}

// A control thread turning parameters (live and structural) while the audio thread runs:
// the output stays finite and under the ceiling (under AddressSanitizer: no memory error).
TEST(EngineFrontEnd, ControlAndAudioThreadsAtOnce) {
    const double fs = 48000;
    const auto x = test::drum_pattern(fs, 4.0, 13).audio;
    const Settings start;
    Engine engine(start);
    engine.enable_frame_queue();
    engine.prepare(fs, 64);
    std::vector<float> y(x.size());
    std::atomic<bool> done{false};
    std::thread control([&] {
        const auto changes = test::turned_live_values(start);
        for (size_t i = 0; !done; ++i) {
            const auto& [id, value] = changes[i % changes.size()];
            if (!spec(id).key.ends_with("weight")) engine.set(id, i % 2 ? value : start[id]);
            if (i % 50 == 0) engine.set(P::onset_window_ms, i % 100 == 0 ? 8.0 : 5.8);
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
    });
    std::thread reader([&] {
        AnalysisFrame frame;
        while (!done) engine.pop_frame(frame);
    });
    for (size_t i = 0; i < x.size(); i += 64) engine.process(x.data() + i, y.data() + i, 64);
    done = true;
    control.join();
    reader.join();
    for (float v : y) ASSERT_TRUE(std::isfinite(v) && std::abs(v) <= 1.0f);
    EXPECT_GT(test::peak(y), 0.05);
}

// The magnitude of y's component at frequency_hz over its first `seconds`.
double component(const std::vector<float>& y, double fs, double frequency_hz, double seconds) {
    double re = 0, im = 0;
    for (size_t i = 0; i < static_cast<size_t>(seconds * fs); ++i) {
        re += y[i] * std::cos(2 * kPi * frequency_hz * i / fs);
        im += y[i] * std::sin(2 * kPi * frequency_hz * i / fs);
    }
    return std::hypot(re, im);
}

TEST(EngineFrontEnd, InjectedTriggersDriveTheSynthesis) {
    const double fs = 48000;
    const std::vector<float> silence(static_cast<size_t>(fs / 2), 0.0f);
    for (double f : {200.0, 300.0}) {
        Engine engine;
        engine.prepare(fs, 64);
        engine.set_program_source(ProgramSource::external);
        engine.trigger(f, 1.0);
        const auto y = test::process_in_blocks(engine, silence, 64);
        EXPECT_GT(test::peak(y), 0.1) << "a pulse from silence";
        for (double other : {f / 2, f * 0.75, f * 1.5})
            EXPECT_GT(component(y, fs, f, 0.05), 2 * component(y, fs, other, 0.05)) << f;
        EXPECT_THROW(engine.trigger(-1, 0.5), std::invalid_argument);
    }
    Engine analysed;  // the analysis alone: silence stays silent
    analysed.prepare(fs, 64);
    EXPECT_EQ(test::peak(test::process_in_blocks(analysed, silence, 64)), 0.0);
}

TEST(EngineFrontEnd, FramesReachAReaderThroughTheQueue) {
    const double fs = 48000;
    const auto drums = test::drum_pattern(fs, 2.0, 2);
    Engine engine;
    engine.enable_frame_queue();
    engine.prepare(fs, 256);
    std::vector<AnalysisFrame> frames;
    AnalysisFrame frame;
    std::vector<float> y(drums.audio.size());
    for (size_t done = 0; done < y.size(); done += 256) {
        const int count = static_cast<int>(std::min<size_t>(256, y.size() - done));
        engine.process(drums.audio.data() + done, y.data() + done, count);
        while (engine.pop_frame(frame)) frames.push_back(frame);
    }
    // 48 kHz is three input samples per analysis sample: frame k ends after the input its last
    // analysis sample reads, (k hop - 1) * 3 + 1 (Analyzer).
    const auto hop = static_cast<int64_t>(engine.hop_samples() / 3);
    ASSERT_EQ(engine.hop_samples(), 3.0 * static_cast<double>(hop));
    ASSERT_EQ(frames.size(), (y.size() + 2) / static_cast<size_t>(3 * hop));
    int onsets = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
        EXPECT_EQ(frames[i].features.frame_end_sample,
                  (static_cast<int64_t>(i + 1) * hop - 1) * 3 + 1);
        onsets += frames[i].features.onset;
        EXPECT_EQ(frames[i].control.trigger, frames[i].features.onset);
    }
    EXPECT_EQ(onsets, static_cast<int>(drums.onsets.size()));
}

}  // namespace
}  // namespace tactus
