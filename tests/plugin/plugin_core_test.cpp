// The plugin's format-neutral parts (apps/plugin): host parameters are the table's rows by
// stable id, host values are clamped and rounded as the table wants them, a float echo of a
// value keeps its double, changes reach the control thread once each, and the state is the
// engine's preset text, refused as a whole (defaults and one line) when it is not valid.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <set>
#include <vector>

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
    const P window = P::analysis_window_ms;  // 23.2: not a float
    host.set_from_host(window, static_cast<float>(spec(window).default_value));
    EXPECT_FALSE(host.changed());
    EXPECT_EQ(host.value(window), spec(window).default_value);
    host.set_from_host(window, 30.0f);
    EXPECT_TRUE(host.changed());
    std::vector<std::pair<P, double>> taken;
    host.for_each_marked([&](P id, double v) { taken.emplace_back(id, v); });
    ASSERT_EQ(taken.size(), 1u);
    EXPECT_EQ(taken[0], std::make_pair(window, 30.0));
    host.for_each_marked([&](P id, double v) { taken.emplace_back(id, v); });
    EXPECT_EQ(taken.size(), 1u);
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
