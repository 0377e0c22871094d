// The plugin's format-neutral parts (apps/plugin): host parameters are the table's rows by
// stable id, host values are clamped and rounded as the table wants them, a float echo of a
// value keeps its double, changes reach the control thread once each, the control thread
// sleeps while nothing changes yet takes a change within its bound, and the state is the
// engine's preset text, refused as a whole (defaults and one line) when it is not valid.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>
#include <thread>
#include <vector>

#include "control_thread.hpp"
#include "host_parameters.hpp"
#include "plugin_params.hpp"
#include "plugin_state.hpp"

namespace tactus::plugin {
namespace {

bool same(const Settings& a, const Settings& b) {
    for (const ParamSpec& s : param_table()) {
        const double x = a[s.param], y = b[s.param];
        if (std::memcmp(&x, &y, sizeof x) != 0) return false;
    }
    return true;
}

TEST(PluginParams, HostIndexIsTheStableId) {
    uint32_t largest = 0;
    std::set<std::string> symbols;
    for (const ParamSpec& s : param_table()) {
        largest = std::max(largest, s.id);
        ASSERT_EQ(param_at(s.id), s.param) << s.key;
        const std::string symbol = identifier_of(s);
        EXPECT_TRUE(symbols.insert(symbol).second) << symbol << " twice";
        EXPECT_TRUE(std::isalpha(static_cast<unsigned char>(symbol[0]))) << symbol;
        for (char c : symbol)
            EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '_') << symbol;
    }
    EXPECT_EQ(parameter_count(), largest + 1);
    EXPECT_FALSE(param_at(kBypassIndex));
}

TEST(PluginParams, HostValuesAreClampedAndWholeWhereTheTableSays) {
    const ParamSpec& hop = spec(P::analysis_hop_ms);
    EXPECT_EQ(from_host(hop, 1e9f), hop.max);
    EXPECT_EQ(from_host(hop, -1e9f), hop.min);
    EXPECT_EQ(from_host(hop, NAN), hop.default_value);
    const ParamSpec& curve = spec(P::amplitude_curve);
    EXPECT_EQ(from_host(curve, 1.4f), 1.0);
    EXPECT_EQ(from_host(curve, 1.6f), 2.0);
}

TEST(HostParameters, AFloatEchoKeepsTheDoubleAndAChangeIsTakenOnce) {
    HostParameters host;
    const P hop = P::analysis_hop_ms;  // 1.45: not a float
    host.set_from_host(hop, static_cast<float>(spec(hop).default_value));
    EXPECT_FALSE(host.changed());
    EXPECT_EQ(host.value(hop), spec(hop).default_value);
    host.set_from_host(hop, 3.0f);
    EXPECT_TRUE(host.changed());
    std::vector<std::pair<P, double>> taken;
    host.for_each_marked([&](P id, double v) { taken.emplace_back(id, v); });
    ASSERT_EQ(taken.size(), 1u);
    EXPECT_EQ(taken[0], std::make_pair(hop, 3.0));
    host.for_each_marked([&](P id, double v) { taken.emplace_back(id, v); });
    EXPECT_EQ(taken.size(), 1u);
}

using Clock = std::chrono::steady_clock;
using Ms = std::chrono::duration<double, std::milli>;

// Idle, an instance's control thread wakes 1000 / kIdlePoll times a second (50), not 1000.
TEST(ControlThread, IdleItWakesAtTheIdlePollOnly) {
    std::atomic<int> runs{0};
    {
        ControlThread thread([&runs] {
            ++runs;
            return false;
        });
        std::this_thread::sleep_for(std::chrono::seconds(1));
    }
    std::printf("control thread idle: %d wake-ups in 1 s\n", runs.load());
    EXPECT_LE(runs.load(), 1000 / ControlThread::kIdlePoll.count() + 5);
    EXPECT_GE(runs.load(), 1000 / ControlThread::kIdlePoll.count() / 2);
}

// A change stored by the audio thread (an atomic, no signal) is taken within kIdlePoll when
// idle, then within kBusyPoll while changes keep coming; wake() takes one at once. The bounds
// allow for scheduling on a loaded machine: the least of several tries is held to them.
TEST(ControlThread, AChangeIsTakenWithinThePoll) {
    std::atomic<bool> pending{false};
    std::atomic<Clock::rep> taken_at{0};
    ControlThread thread([&] {
        if (!pending.exchange(false)) return false;
        taken_at = Clock::now().time_since_epoch().count();
        return true;
    });
    const auto delay_ms = [&](bool wake) {
        taken_at = 0;
        const Clock::time_point start = Clock::now();
        pending = true;
        if (wake) thread.wake();
        while (taken_at == 0) std::this_thread::sleep_for(std::chrono::microseconds(100));
        return Ms(Clock::time_point(Clock::duration(taken_at.load())) - start).count();
    };
    double idle = 1e9, busy = 1e9, woken = 1e9;
    for (int i = 0; i < 5; ++i) {
        std::this_thread::sleep_for(ControlThread::kBusyFor + ControlThread::kIdlePoll);
        idle = std::min(idle, delay_ms(false));
        busy = std::min(busy, delay_ms(false));  // within kBusyFor of the last change
        std::this_thread::sleep_for(ControlThread::kBusyFor + ControlThread::kIdlePoll);
        woken = std::min(woken, delay_ms(true));
    }
    std::printf("change taken: idle %.2f ms, during a run %.2f ms, woken %.2f ms\n", idle, busy,
                woken);
    EXPECT_LE(idle, Ms(ControlThread::kIdlePoll).count() + 2);
    EXPECT_LE(busy, Ms(ControlThread::kBusyPoll).count() + 2);
    EXPECT_LE(woken, 2.0);
}

TEST(PluginState, RoundTripsBitForBit) {
    Settings settings;
    settings.set(P::analysis_window_ms, 17.123456789);
    settings.set(P::frequency_out_max, 1.0 / 3.0 * 900);
    settings.set(P::amplitude_curve, 0);
    const RestoredState restored = restore_state(state_text(settings));
    EXPECT_EQ(restored.error, "");
    EXPECT_TRUE(same(restored.settings, settings));
}

TEST(PluginState, AnythingButAValidStateGivesTheDefaultsAndOneLine) {
    Settings changed;
    changed.set(P::frequency_out_max, 250);
    std::string good = state_text(changed);
    const auto replaced = [&](std::string_view from, std::string_view to) {
        std::string s = good;
        return s.replace(s.find(from), from.size(), to);
    };
    for (const std::string& bad :
         {replaced("format = 1", "format = 2"), replaced("out_max = 250.0", "out_max = 'x'"),
          replaced("out_max = 250.0", "out_max = -5"), replaced("[mapping]", "[mapping"),
          replaced("out_max = 250.0", "gain = 1"), std::string("\xff\xfe\x00garbage", 10),
          good.substr(0, good.size() / 2) + "\n[[", std::string("{\"json\": true}")}) {
        const RestoredState r = restore_state(bad);
        EXPECT_FALSE(r.error.empty()) << bad;
        EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
        EXPECT_TRUE(same(r.settings, Settings{})) << bad;
    }
}

}  // namespace
}  // namespace tactus::plugin
