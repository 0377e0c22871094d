// Routes (engine/route.hpp): each actuator output plays its own part of the input. The text
// form reads back; with every output on `all` the engine is today's, bit for bit; a channel
// route carries a hard-left pan to the left actuator only; a low band route stays quiet while a
// voice above it plays alone; kick and snare routes each play their own part's hits and hardly
// the other's (at parts.route_min 0, every drum hit); an overlay shapes only its output; every
// kind is block-size invariant; routes changed while audio runs play as routes set from the
// start once the crossfade is over, and so do whole outputs (profiles, trims) changed at once;
// a channel the input lacks is refused at prepare, naming the actuator (a mono input is every
// channel).
#include "tactus/engine/route.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "support/signals.hpp"
#include "support/sounds.hpp"
#include "tactus/actuator/profile.hpp"
#include "tactus/core/units.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/audio_reader.hpp"

namespace tactus {
namespace {

using Channels = std::vector<std::vector<float>>;

std::vector<ActuatorOutput> outputs_for(const std::vector<std::string>& routes) {
    std::vector<ActuatorOutput> outputs;
    for (const auto& r : routes) outputs.push_back({.profile = {}, .route = Route::parse(r)});
    return outputs;
}

// Every output of `engine` (prepared for in.size() channels) for `in`, in blocks cycling
// through `blocks`.
Channels run_routes(Engine& engine, const Channels& in, const std::vector<int>& blocks) {
    const size_t n = in.front().size();
    Channels out(static_cast<size_t>(engine.actuators()), std::vector<float>(n));
    std::vector<const float*> ins(in.size());
    std::vector<float*> outs(out.size());
    for (size_t done = 0, b = 0; done < n; ++b) {
        const auto count =
            std::min<size_t>(n - done, static_cast<size_t>(blocks[b % blocks.size()]));
        for (size_t c = 0; c < in.size(); ++c) ins[c] = in[c].data() + done;
        for (size_t k = 0; k < out.size(); ++k) outs[k] = out[k].data() + done;
        engine.process(ins.data(), outs.data(), static_cast<int>(count));
        done += count;
    }
    return out;
}

Channels render_routes(const Channels& in, double fs, const std::vector<std::string>& routes,
                       const std::vector<int>& blocks = {480}, const Settings& settings = {}) {
    Engine engine(settings);
    engine.set_actuators(outputs_for(routes));
    engine.prepare({.sample_rate_hz = fs,
                    .max_block = Engine::kMaxBlock,
                    .channels = static_cast<int>(in.size())});
    return run_routes(engine, in, blocks);
}

double energy_of(std::span<const float> x) {
    double sum = 0;
    for (const float v : x) sum += double(v) * v;
    return sum;
}

TEST(Route, ReadsBackFromItsText) {
    for (const char* text : {"all", "kick", "snare+hat", "kick+snare+hat+other", "band:20-120",
                             "band:150.5-2000", "channel:1", "channel:16"})
        EXPECT_EQ(Route::parse(text).text(), text);
    EXPECT_EQ(Route::parse("hat+kick").text(), "kick+hat") << "parts in their order";
    EXPECT_TRUE(Route::parse("band:20-120").own_analysis());
    EXPECT_FALSE(Route::parse("kick").own_analysis());
    EXPECT_TRUE(Route::parse("kick").plays(DrumPart::kick));
    EXPECT_FALSE(Route::parse("kick").plays(DrumPart::snare));
}

TEST(Route, RefusesAnUnknownTextNamingItAndWhatIsAllowed) {
    for (const char* bad : {"", "kicks", "kick+", "band:120-20", "band:5-100", "band:20-9000",
                            "band:20", "band:a-b", "channel:0", "channel:17", "channel:x", "ALL"})
        EXPECT_THAT([&] { Route::parse(bad); },
                    testing::ThrowsMessage<std::invalid_argument>(
                        testing::AllOf(testing::HasSubstr(std::string("route '") + bad + "'"),
                                       testing::HasSubstr("band:LOW-HIGH"))))
            << bad;
}

TEST(Route, AnOverlaySetsOnlyTheMappingsLiveParameters) {
    EXPECT_NO_THROW(check_overlay(
        {{P::frequency_out_max, 80}, {P::envelope_decay_ms, 300}, {P::parts_kick_gain_db, -6}}));
    EXPECT_THAT(
        [] {
            check_overlay({{P::post_ceiling_db, -6}});
        },
        testing::ThrowsMessage<std::invalid_argument>(
            testing::HasSubstr("post.ceiling_db: an output may set only")));
    EXPECT_THAT(
        [] {
            check_overlay({{P::frequency_out_max, 1e6}});
        },
        testing::ThrowsMessage<std::invalid_argument>(
            testing::HasSubstr("mapping.frequency.out_max")));
}

TEST(Routes, OutputsOnAllAreTheOneOutputEngineBitForBit) {
    const double fs = 48000;
    const Channels x{test::drum_pattern(fs, 4.0, 3).audio};
    const auto one = render_routes(x, fs, {"all"});
    const auto three = render_routes(x, fs, {"all", "kick", "all"});
    EXPECT_TRUE(test::same_bits(three[0], one[0]));
    EXPECT_TRUE(test::same_bits(three[2], one[0]));
    EXPECT_FALSE(test::same_bits(three[1], one[0]));
}

TEST(Routes, AChannelRouteCarriesAHardLeftPanToTheLeftActuatorOnly) {
    const MonoAudio amen = read_mono(test::kAmen);
    const std::vector<float> silent(amen.samples.size(), 0.0f);
    const auto out =
        render_routes({amen.samples, silent}, amen.sample_rate_hz, {"channel:1", "channel:2"});
    ASSERT_GT(energy_of(out[0]), 0.0);
    EXPECT_EQ(energy_of(out[1]), 0.0);
    // Panned 0.8 / 0.2 (-12 dB on the right): both felt, the left far more.
    std::vector<float> left = amen.samples, right = amen.samples;
    for (auto& v : left) v *= 0.8f;
    for (auto& v : right) v *= 0.2f;
    const auto panned =
        render_routes({left, right}, amen.sample_rate_hz, {"channel:1", "channel:2"});
    EXPECT_GT(energy_of(panned[1]), 0.0);
    EXPECT_GT(energy_of(panned[0]), 2 * energy_of(panned[1]));
}

// A voice-like tone (syllables of a 220 Hz sawtooth, 4 a second: nothing below 200 Hz) alone
// for 2 s, then with 55 Hz kicks: the band:20-120 route's output while the voice plays alone is
// under 5 % of its energy, while the whole input's route does feel the voice.
TEST(Routes, ALowBandRouteStaysQuietWhileOnlyAVoiceAbovePlays) {
    const double fs = 48000;
    const auto n = static_cast<size_t>(4 * fs);
    std::vector<float> x = test::sawtooth(220, fs, n, 0.3);
    for (size_t i = 0; i < n; ++i) {  // 200 ms syllables, 50 ms apart, 10 ms fades
        const double t = std::fmod(static_cast<double>(i) / fs, 0.25);
        x[i] *= static_cast<float>(std::clamp(std::min(t, 0.2 - t) / 0.01, 0.0, 1.0));
    }
    for (size_t start = 2 * static_cast<size_t>(fs); start < n; start += 24000)
        for (size_t i = 0; i < 12000 && start + i < n; ++i) {
            const double t = static_cast<double>(i) / fs;
            x[start + i] +=
                static_cast<float>(0.6 * std::exp(-t / 0.08) * std::sin(2 * kPi * 55 * t));
        }
    const auto out = render_routes({x}, fs, {"band:20-120", "all"});
    const auto alone = static_cast<size_t>(2 * fs);
    const double all = energy_of(out[0]);
    ASSERT_GT(all, 0.0);
    EXPECT_LT(energy_of(std::span(out[0]).first(alone)), 0.05 * all);
    EXPECT_GT(energy_of(std::span(out[1]).first(alone)),
              0.1 * energy_of(std::span(out[1]).subspan(alone)))
        << "the whole input's route does feel the voice";
}

// Eight kicks and eight snares in turn, 400 ms apart: each part's route gives each of its
// part's hits a pulse, and the other part's hits reach it at least 10 dB weaker (peak).
TEST(Routes, KickAndSnareRoutesEachPlayTheirOwnPartsHits) {
    const MonoAudio kick = read_mono("/usr/share/sonic-pi/samples/bd_haus.flac");
    const MonoAudio snare = read_mono("/usr/share/sonic-pi/samples/sn_dolf.flac");
    const double fs = kick.sample_rate_hz;
    ASSERT_EQ(snare.sample_rate_hz, fs);
    const auto spacing = static_cast<size_t>(0.4 * fs);
    std::vector<float> x(17 * spacing, 0.0f);
    for (size_t h = 0; h < 16; ++h) {
        const auto& hit = h % 2 == 0 ? kick.samples : snare.samples;
        for (size_t i = 0; i < hit.size() && i < spacing; ++i) x[(h + 1) * spacing + i] += hit[i];
    }
    const auto out = render_routes({x}, fs, {"kick", "snare"});
    for (size_t h = 0; h < 16; ++h) {
        const auto window = std::span(out[0]).subspan((h + 1) * spacing, spacing);
        const double own =
            test::peak(h % 2 == 0 ? window : std::span(out[1]).subspan((h + 1) * spacing, spacing));
        const double other =
            test::peak(h % 2 == 0 ? std::span(out[1]).subspan((h + 1) * spacing, spacing) : window);
        EXPECT_GT(own, 0.1) << "hit " << h;
        EXPECT_LT(other, own * std::pow(10.0, -10.0 / 20)) << "hit " << h;
    }
    // parts.route_min: at 1 only the hits named a route's part; at 0 a part route plays every
    // drum hit, whatever it is named, and the kick output plays the snares too.
    for (const double route_min : {1.0, 0.0}) {
        Settings settings;
        settings.set(P::parts_route_min, route_min);
        const auto y = render_routes({x}, fs, {"kick", "snare"}, {480}, settings);
        int snares_on_kick = 0;
        for (size_t h = 1; h < 16; h += 2)
            snares_on_kick += test::peak(std::span(y[0]).subspan((h + 1) * spacing, spacing)) > 0.1;
        EXPECT_EQ(snares_on_kick, route_min == 1 ? 0 : 8) << "parts.route_min " << route_min;
    }
}

TEST(Routes, AnOverlayShapesOnlyItsOwnOutput) {
    const double fs = 48000;
    const Channels x{test::drum_pattern(fs, 3.0, 5).audio};
    std::vector<ActuatorOutput> outputs = outputs_for({"all", "all"});
    outputs[1].overlay = {{P::frequency_out_min, 300}, {P::frequency_out_max, 400}};
    Engine engine;
    engine.set_actuators(outputs);
    engine.prepare({.sample_rate_hz = fs, .max_block = 512, .channels = 1});
    const auto out = run_routes(engine, x, {512});
    EXPECT_TRUE(test::same_bits(out[0], render_routes(x, fs, {"all"}, {512})[0]));
    const auto crossings = [](const std::vector<float>& y) {
        int n = 0;
        for (size_t i = 1; i < y.size(); ++i) n += (y[i - 1] < 0) != (y[i] < 0);
        return n;
    };
    EXPECT_GT(crossings(out[1]), 2 * crossings(out[0])) << "a higher pitch range";
}

// Each output plays its own actuator's fit, its overlay fitted too: an LRA's output asking for
// 500-1000 Hz plays within the LRA's band, and an output without a profile beside it plays the
// overlay as asked, not the LRA's band.
TEST(Routes, EachOutputPlaysItsOwnProfilesFitOfItsOverlay) {
    const double fs = 48000;
    const Channels x{test::drum_pattern(fs, 3.0, 5).audio};
    const ActuatorProfile lra = load_actuator(resolve_actuator("lra-175"));
    std::vector<ActuatorOutput> outputs = outputs_for({"all", "all"});
    for (ActuatorOutput& o : outputs)
        o.overlay = {{P::frequency_out_min, 500}, {P::frequency_out_max, 1000}};
    outputs[0].profile = lra;
    Engine engine;
    engine.set_actuators(outputs);
    engine.enable_frame_queue();
    engine.prepare({.sample_rate_hz = fs, .max_block = 512, .channels = 1});
    run_routes(engine, x, {512});
    std::vector<double> lowest(2, INFINITY), highest(2, 0);
    for (LaneFrame f; engine.pop_lane_frame(f);) {
        if (f.control.amplitude <= 0) continue;
        const auto k = static_cast<size_t>(f.lane);
        lowest[k] = std::min(lowest[k], f.control.frequency_hz);
        highest[k] = std::max(highest[k], f.control.frequency_hz);
    }
    std::printf("LRA output: %.0f-%.0f Hz; no profile: %.0f-%.0f Hz\n", lowest[0], highest[0],
                lowest[1], highest[1]);
    EXPECT_GE(lowest[0], lra.band_low_hz);
    EXPECT_LE(highest[0], lra.band_high_hz);
    EXPECT_GE(lowest[1], 500);
    EXPECT_GT(highest[1], 700);
}

TEST(Routes, EveryKindIsBlockSizeInvariant) {
    const MonoAudio amen = read_mono(test::kAmen);
    std::vector<float> right = amen.samples;
    for (auto& v : right) v *= 0.5f;
    const Channels x{amen.samples, right};
    const std::vector<std::string> routes{"all", "kick+hat", "band:40-200", "channel:2"};
    const auto reference = render_routes(x, amen.sample_rate_hz, routes, {4096});
    for (const auto& blocks : std::vector<std::vector<int>>{{1, 7, 480}, {64}, {333, 17}}) {
        const auto y = render_routes(x, amen.sample_rate_hz, routes, blocks);
        for (size_t k = 0; k < routes.size(); ++k)
            EXPECT_TRUE(test::same_bits(y[k], reference[k]))
                << routes[k] << " in blocks of " << blocks[0];
    }
}

// Routes changed mid-file: once the crossfade is over, the output is the one of an engine given
// those routes from the start (its new pipeline was primed with what the input was).
TEST(Routes, ChangedWhileAudioRunsTheyPlayAsIfSetFromTheStart) {
    const MonoAudio amen = read_mono(test::kAmen);
    const double fs = amen.sample_rate_hz;
    std::vector<float> right = amen.samples;
    for (auto& v : right) v *= 0.25f;
    const Channels x{amen.samples, right};
    constexpr int kBlock = 64;
    const std::vector<std::string> after{"band:30-150", "channel:2", "snare"};
    const auto reference = render_routes(x, fs, after, {kBlock});
    Engine engine;
    engine.set_actuators(outputs_for({"all", "all", "all"}));
    engine.prepare({.sample_rate_hz = fs, .max_block = kBlock, .channels = 2});
    const auto change_at = static_cast<size_t>(3.0 * fs) / kBlock * kBlock;
    Channels first{std::vector<float>(x[0].begin(), x[0].begin() + static_cast<long>(change_at)),
                   std::vector<float>(x[1].begin(), x[1].begin() + static_cast<long>(change_at))};
    const auto before = run_routes(engine, first, {kBlock});
    engine.set_outputs(outputs_for(after));
    EXPECT_EQ(engine.outputs()[1].route.text(), "channel:2");
    Channels rest{std::vector<float>(x[0].begin() + static_cast<long>(change_at), x[0].end()),
                  std::vector<float>(x[1].begin() + static_cast<long>(change_at), x[1].end())};
    const auto y = run_routes(engine, rest, {kBlock});
    const auto settled = static_cast<size_t>(0.05 * fs);
    for (size_t k = 0; k < after.size(); ++k) {
        const auto ref = std::span(reference[k]).subspan(change_at + settled);
        const double peak = test::peak(ref);
        ASSERT_GT(peak, 0.01) << after[k];
        double largest = 0;
        for (size_t i = settled; i < y[k].size(); ++i)
            largest = std::max(largest, std::abs(double(y[k][i]) - reference[k][change_at + i]));
        EXPECT_LT(largest, 1e-3 * peak) << after[k];
        EXPECT_GT(test::peak(std::span(y[k]).first(settled)), 0.0) << after[k] << ": no gap";
    }
    EXPECT_GT(test::peak(before[0]), 0.0);
}

// A layout changed while audio runs (Engine::set_outputs): routes, an overlay, profiles and
// trims at once, as if set from the start once the crossfade (and the trims' glide) is over; a
// changed delay is refused, having changed nothing.
TEST(Routes, OutputsChangedWhileAudioRunsPlayAsIfSetFromTheStart) {
    const MonoAudio amen = read_mono(test::kAmen);
    const double fs = amen.sample_rate_hz;
    const Channels x{amen.samples};
    constexpr int kBlock = 64;
    std::vector<ActuatorOutput> after = outputs_for({"band:30-150", "snare"});
    after[0].profile = load_actuator(resolve_actuator("lra-175"));
    after[1].profile = load_actuator(resolve_actuator("voice-coil"));
    after[1].gain_db = -6;
    after[1].overlay = {{P::frequency_out_max, 200}};
    Engine from_start;
    from_start.set_actuators(after);
    from_start.prepare({.sample_rate_hz = fs, .max_block = kBlock});
    const Channels reference = run_routes(from_start, x, {kBlock});
    Engine engine;
    engine.set_actuators(outputs_for({"all", "all"}));
    engine.prepare({.sample_rate_hz = fs, .max_block = kBlock});
    const auto change_at = static_cast<size_t>(3.0 * fs) / kBlock * kBlock;
    run_routes(engine, {std::vector<float>(x[0].begin(), x[0].begin() + long(change_at))},
               {kBlock});
    std::vector<ActuatorOutput> delayed = after;
    delayed[1].delay_ms = 5;
    EXPECT_THAT([&] { engine.set_outputs(delayed); },
                testing::ThrowsMessage<std::invalid_argument>(
                    testing::HasSubstr("actuator 1: delay 5 ms: a delay is set before prepare")));
    EXPECT_FALSE(engine.outputs()[0].profile) << "nothing changed";
    engine.set_outputs(after);
    EXPECT_EQ(engine.outputs()[1].gain_db, -6);
    const Channels y = run_routes(
        engine, {std::vector<float>(x[0].begin() + long(change_at), x[0].end())}, {kBlock});
    const auto settled = static_cast<size_t>(0.05 * fs);
    for (size_t k = 0; k < after.size(); ++k) {
        const auto ref = std::span(reference[k]).subspan(change_at + settled);
        const double peak = test::peak(ref);
        ASSERT_GT(peak, 0.01) << k;
        double largest = 0;
        for (size_t i = settled; i < y[k].size(); ++i)
            largest = std::max(largest, std::abs(double(y[k][i]) - reference[k][change_at + i]));
        std::printf(
            "output %zu, changed live vs set from the start: largest difference %.3g "
            "(peak %.3g)\n",
            k, largest, peak);
        EXPECT_LT(largest, 1e-3 * peak) << k;
        EXPECT_GT(test::peak(std::span(y[k]).first(settled)), 0.0) << k << ": no gap";
    }
}

TEST(Routes, AChannelTheInputLacksIsRefusedNamingTheActuator) {
    Engine engine;
    engine.set_actuators(outputs_for({"all", "channel:3"}));
    EXPECT_THAT([&] { engine.prepare({.sample_rate_hz = 48000, .max_block = 64, .channels = 2}); },
                testing::ThrowsMessage<std::invalid_argument>(
                    testing::HasSubstr("actuator 1: route channel:3 takes input channel 3")));
    const Channels mono{test::drum_pattern(48000, 2.0, 9).audio};
    const auto both = render_routes(mono, 48000, {"channel:1", "channel:3"});
    EXPECT_GT(test::peak(both[0]), 0.05);
    EXPECT_TRUE(test::same_bits(both[1], both[0])) << "a mono input is every channel";
    Engine prepared;
    prepared.set_actuators(outputs_for({"all"}));
    prepared.prepare({.sample_rate_hz = 48000, .max_block = 64, .channels = 2});
    EXPECT_THROW(prepared.set_outputs(outputs_for({"channel:4"})), std::invalid_argument);
    EXPECT_THROW(prepared.set_outputs({}), std::invalid_argument) << "one per actuator";
    EXPECT_EQ(prepared.outputs()[0].route.text(), "all") << "nothing changed";
}

}  // namespace
}  // namespace tactus
