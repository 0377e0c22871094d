// The parameter table and Settings: every default lies in its range, keys are unique and
// findable, set() rejects out-of-range and non-finite values with the key and the allowed range
// in the message, choices round and parse by name, text_of round-trips, nearest_param suggests.
#include "tactus/params/params.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

namespace tactus {
namespace {

using ::testing::HasSubstr;

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no exception)";
}

TEST(Params, TableIsCompleteAndDefaultsAreInRange) {
    const auto table = param_table();
    ASSERT_EQ(table.size(), static_cast<size_t>(P::count));
    std::set<std::string_view> keys;
    const Settings defaults;
    for (size_t i = 0; i < table.size(); ++i) {
        const ParamSpec& s = table[i];
        const P id = static_cast<P>(i);
        EXPECT_TRUE(keys.insert(s.key).second) << "duplicate key " << s.key;
        EXPECT_LT(s.min, s.max) << s.key;
        EXPECT_GE(s.default_value, s.min) << s.key;
        EXPECT_LE(s.default_value, s.max) << s.key;
        EXPECT_EQ(defaults[id], s.default_value) << s.key;
        EXPECT_FALSE(s.help.empty()) << s.key;
        EXPECT_EQ(&spec(id), &table[i]);
        ASSERT_TRUE(find_param(s.key).has_value()) << s.key;
        EXPECT_EQ(*find_param(s.key), id);
        if (!s.choices.empty()) {
            EXPECT_FALSE(s.choices.empty()) << s.key;
            EXPECT_EQ(s.max, static_cast<double>(s.choices.size() - 1)) << s.key;
            EXPECT_EQ(defaults[id], std::round(defaults[id])) << s.key;
        }
    }
    EXPECT_EQ(spec(P::envelope_decay_ms).key, "envelope.decay_ms");
    EXPECT_EQ(spec(P::frequency_out_max).key, "mapping.frequency.out_max");
    EXPECT_EQ(spec(P::post_release_ms).key, "post.release_ms");
    EXPECT_EQ(spec(P::square_mix_smoothing_ms).key, "mapping.square_mix.smoothing_ms");
    EXPECT_FALSE(find_param("no.such.key").has_value());
}

// ParamCurve::log tells a front end to lay the range out logarithmically: that needs min > 0.
TEST(Params, LogScaledParametersHavePositiveRanges) {
    for (const ParamSpec& s : param_table())
        if (s.curve == ParamCurve::log) {
            EXPECT_GT(s.min, 0.0) << s.key << " is log-scaled but its range starts at " << s.min;
        }
}

TEST(Params, SetAcceptsTheRangeEndsAndRejectsBeyond) {
    for (size_t i = 0; i < param_table().size(); ++i) {
        const ParamSpec& s = param_table()[i];
        const P id = static_cast<P>(i);
        Settings settings;
        settings.set(id, s.min);
        EXPECT_EQ(settings[id], s.min) << s.key;
        settings.set(id, s.max);
        EXPECT_EQ(settings[id], s.max) << s.key;
        const double span = s.max - s.min;
        for (double bad :
             {s.min - 0.01 * span, s.max + 0.01 * span, std::numeric_limits<double>::quiet_NaN(),
              std::numeric_limits<double>::infinity()}) {
            const std::string m = message_of([&] { settings.set(id, bad); });
            EXPECT_THAT(m, HasSubstr(std::string(s.key))) << bad;
            EXPECT_THAT(m, HasSubstr("out of range")) << s.key;
            EXPECT_THAT(m, HasSubstr(fmt::format("{} to {}", s.min, s.max))) << s.key << ": " << m;
            EXPECT_EQ(settings[id], s.max) << "a rejected value must not be stored: " << s.key;
        }
    }
}

TEST(Params, OutOfRangeMessageNamesKeyRangeAndUnit) {
    Settings settings;
    const std::string m = message_of([&] { settings.set(P::envelope_decay_ms, 1.0); });
    EXPECT_THAT(m, HasSubstr("envelope.decay_ms"));
    EXPECT_THAT(m, HasSubstr("5 to 5000 ms"));
    EXPECT_THROW(settings.set(P::envelope_decay_ms, 1.0), std::invalid_argument);
}

TEST(Params, ChoicesRoundAndParseByName) {
    Settings settings;
    settings.set(P::amplitude_curve, 1.4);
    EXPECT_EQ(settings[P::amplitude_curve], 1.0);
    EXPECT_EQ(settings.text_of(P::amplitude_curve), "log");
    settings.set_from_text(P::frequency_source, "pitch_hz");
    EXPECT_EQ(settings[P::frequency_source], static_cast<double>(FeatureSource::pitch_hz));
    EXPECT_EQ(settings.text_of(P::frequency_source), "pitch_hz");
    const std::string m = message_of([&] { settings.set_from_text(P::amplitude_curve, "cubic"); });
    EXPECT_THAT(m, HasSubstr("mapping.amplitude.curve"));
    EXPECT_THAT(m, HasSubstr("lin, log, exp"));
}

TEST(Params, NumbersParseStrictly) {
    Settings settings;
    settings.set_from_text(P::envelope_decay_ms, "120");
    EXPECT_EQ(settings[P::envelope_decay_ms], 120.0);
    settings.set_from_text(P::post_drive_db, "-3.5");
    EXPECT_EQ(settings[P::post_drive_db], -3.5);
    settings.set_from_text(P::post_release_ms, "1e2");
    EXPECT_EQ(settings[P::post_release_ms], 100.0);
    for (const char* bad : {"", "abc", "12ms", " 5", "5 ", "nan", "inf", "1,5"})
        EXPECT_THROW(settings.set_from_text(P::envelope_decay_ms, bad), std::invalid_argument)
            << "'" << bad << "'";
    EXPECT_EQ(settings[P::envelope_decay_ms], 120.0);
}

TEST(Params, TextOfRoundTrips) {
    const Settings defaults;
    for (size_t i = 0; i < param_table().size(); ++i) {
        const P id = static_cast<P>(i);
        Settings copy;
        copy.set_from_text(id, defaults.text_of(id));
        EXPECT_EQ(copy[id], defaults[id]) << param_table()[i].key;
    }
}

TEST(Params, NearestParamSuggestsTheClosestKey) {
    EXPECT_EQ(nearest_param("envelope.decay"), "envelope.decay_ms");
    EXPECT_EQ(nearest_param("post.band_hi_hz"), "post.band_high_hz");
    EXPECT_EQ(nearest_param("mapping.frequency.outmax"), "mapping.frequency.out_max");
    EXPECT_EQ(nearest_param("envelope.decay_ms"), "envelope.decay_ms");
}

}  // namespace
}  // namespace tactus
