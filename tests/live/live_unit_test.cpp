// The live front end's parts that need no device: the OSC address space generated from the
// parameter table, OSC packets and bundles as they arrive, the server's handling of a burst
// (coalescing, refusals), --osc-port and channel lists, the status line.
#include <gtest/gtest.h>
#include <lo/lo.h>

#include <chrono>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>

#include "live/channel_list.hpp"
#include "live/osc_packet.hpp"
#include "live/osc_server.hpp"
#include "live/preset_watcher.hpp"
#include "live/status_line.hpp"
#include "support/temp_dir.hpp"
#include "tactus/io/preset.hpp"

namespace tactus::live {
namespace {

std::vector<std::byte> packet(const char* address, const char* types, ...) {
    lo_message m = lo_message_new();
    va_list args;
    va_start(args, types);
    for (const char* t = types; *t; ++t) {
        if (*t == 'f') lo_message_add_float(m, static_cast<float>(va_arg(args, double)));
        if (*t == 'i') lo_message_add_int32(m, va_arg(args, int));
        if (*t == 's') lo_message_add_string(m, va_arg(args, const char*));
    }
    va_end(args);
    size_t size = 0;
    void* bytes = lo_message_serialise(m, address, nullptr, &size);
    std::vector<std::byte> out(static_cast<std::byte*>(bytes),
                               static_cast<std::byte*>(bytes) + size);
    std::free(bytes);
    lo_message_free(m);
    return out;
}

TEST(OscAddressSpace, EveryParameterOfTheTableHasItsAddress) {
    const auto lines = osc_address_lines();
    EXPECT_EQ(lines.size(), param_table().size() + 5);
    for (const ParamSpec& s : param_table()) {
        const std::string address = "/tactus/" + std::string(s.key);
        EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [&](const std::string& l) {
            return l.starts_with(address + " ");
        })) << address;
        const OscCommand c = parse_osc({address, {OscArg{'d', s.default_value, ""}}}, 1);
        ASSERT_TRUE(std::holds_alternative<SetParameter>(c)) << address;
        EXPECT_EQ(std::get<SetParameter>(c).id, s.param);
        EXPECT_EQ(std::get<SetParameter>(c).value, s.default_value);
        const OscCommand asked = parse_osc({address, {}}, 1);  // no value: a question
        ASSERT_TRUE(std::holds_alternative<QueryParameter>(asked)) << address;
        EXPECT_EQ(std::get<QueryParameter>(asked).id, s.param);
    }
}

TEST(OscAddressSpace, ChoicesByNameTogglesAsBooleans) {
    const auto c = parse_osc({"/tactus/mapping.frequency.curve", {OscArg{'s', 0, "log"}}}, 1);
    EXPECT_EQ(std::get<SetParameter>(c).value, 1.0);
    const auto t = parse_osc({"/tactus/actuator.dc", {OscArg{'T', 1, ""}}}, 1);
    EXPECT_EQ(std::get<SetParameter>(t).value, 1.0);
}

TEST(OscAddressSpace, PresetTriggerAndActuatorGain) {
    EXPECT_EQ(std::get<LoadPreset>(parse_osc({"/tactus/preset", {OscArg{'s', 0, "tfd"}}}, 1)).name,
              "tfd");
    const auto t = std::get<TriggerPulse>(
        parse_osc({"/tactus/trigger", {OscArg{'f', 120, ""}, OscArg{'i', 1, ""}}}, 1));
    EXPECT_TRUE(t.with_values);
    EXPECT_EQ(t.frequency_hz, 120);
    EXPECT_FALSE(std::get<TriggerPulse>(parse_osc({"/tactus/trigger", {}}, 1)).with_values);
    const auto g =
        std::get<ActuatorGain>(parse_osc({"/tactus/actuator/3/gain", {OscArg{'f', -6, ""}}}, 4));
    EXPECT_EQ(g.actuator, 2);
    EXPECT_EQ(g.gain_db, -6);
    const auto r = std::get<ActuatorRoute>(
        parse_osc({"/tactus/actuator/2/route", {OscArg{'s', 0, "band:20-120"}}}, 2));
    EXPECT_EQ(r.actuator, 1);
    EXPECT_EQ(r.route.text(), "band:20-120");
    EXPECT_EQ(
        std::get<LoadLayout>(parse_osc({"/tactus/layout", {OscArg{'s', 0, "controller"}}}, 2)).name,
        "controller");
}

// Untrusted input: every one of these is refused with one line naming the address.
TEST(OscAddressSpace, RefusesWhatIsNotInTheTable) {
    const std::vector<OscMessage> bad = {
        {"/tactus/post.drive", {OscArg{'f', 1, ""}}},         // unknown key
        {"/other/post.drive_db", {OscArg{'f', 1, ""}}},       // outside /tactus
        {"/tactus/post.drive_db", {OscArg{'f', 1e9, ""}}},    // out of range
        {"/tactus/post.drive_db", {OscArg{'d', NAN, ""}}},    // not finite
        {"/tactus/post.drive_db", {OscArg{'s', 0, "loud"}}},  // wrong type
        {"/tactus/post.drive_db", {OscArg{'b', 0, ""}}},      // a blob
        {"/tactus/post.drive_db", {OscArg{'f', 1, ""}, OscArg{'f', 1, ""}}},
        {"/tactus/mapping.frequency.curve", {OscArg{'s', 0, "cubic"}}},
        {"/tactus/preset", {OscArg{'s', 0, "/etc/passwd"}}},  // a file: never read
        {"/tactus/preset", {OscArg{'s', 0, "../presets/tfd"}}},
        {"/tactus/preset", {OscArg{'f', 1, ""}}},
        {"/tactus/trigger", {OscArg{'f', 120, ""}}},
        {"/tactus/trigger", {OscArg{'f', 1e6, ""}, OscArg{'f', 0.5, ""}}},
        {"/tactus/trigger", {OscArg{'f', 120, ""}, OscArg{'f', 2, ""}}},
        {"/tactus/actuator/0/gain", {OscArg{'f', -6, ""}}},
        {"/tactus/actuator/2/gain", {OscArg{'f', -6, ""}}},  // one actuator only
        {"/tactus/actuator/1/gain", {OscArg{'f', 6, ""}}},   // above 0 dB
        {"/tactus/actuator/1/trim", {OscArg{'f', -6, ""}}},
        {"/tactus/actuator/1/route", {OscArg{'s', 0, "kicks"}}},  // no such route
        {"/tactus/actuator/1/route", {OscArg{'f', 1, ""}}},
        {"/tactus/actuator/2/route", {OscArg{'s', 0, "all"}}},         // one actuator only
        {"/tactus/layout", {OscArg{'s', 0, "/etc/controller.toml"}}},  // a file: never read
        {"/tactus/layout", {}},
        {std::string("/tactus/post.drive_db\n2nd line"), {OscArg{'f', 1, ""}}},
    };
    for (const OscMessage& m : bad) {
        try {
            parse_osc(m, 1);
            ADD_FAILURE() << "accepted " << m.address;
        } catch (const std::invalid_argument& e) {
            const std::string what = e.what();
            EXPECT_TRUE(what.starts_with("osc /")) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
    }
}

TEST(OscPacket, MessagesAndBundles) {
    const auto one = packet("/tactus/post.drive_db", "f", 6.0);
    const auto messages = decode_osc_packet(one);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_EQ(messages[0].address, "/tactus/post.drive_db");
    ASSERT_EQ(messages[0].args.size(), 1u);
    EXPECT_EQ(messages[0].args[0].number, 6.0);

    lo_bundle b = lo_bundle_new(LO_TT_IMMEDIATE);
    lo_message m1 = lo_message_new(), m2 = lo_message_new();
    lo_message_add_float(m1, 3);
    lo_message_add_string(m2, "tfd");
    lo_bundle_add_message(b, "/tactus/post.drive_db", m1);
    lo_bundle_add_message(b, "/tactus/preset", m2);
    size_t size = 0;
    void* bytes = lo_bundle_serialise(b, nullptr, &size);
    const auto bundled = decode_osc_packet({static_cast<std::byte*>(bytes), size});
    std::free(bytes);
    lo_bundle_free_recursive(b);
    ASSERT_EQ(bundled.size(), 2u);
    EXPECT_EQ(bundled[1].args[0].text, "tfd");

    for (std::vector<std::byte> broken :
         {std::vector<std::byte>{}, std::vector<std::byte>(one.begin(), one.end() - 3),
          std::vector<std::byte>(7, std::byte{'#'})})
        EXPECT_THROW(decode_osc_packet(broken), std::invalid_argument);
}

// A burst: the last value of each parameter applies, refusals are one line each and change
// nothing, a preset applies in order with the parameters around it.
TEST(OscServerHandling, CoalescesABurstAndRefusesTheBad) {
    Engine engine;
    engine.set_actuators(std::vector<ActuatorOutput>(2));
    LiveControl control(engine, {"post.release_ms=100"});
    std::vector<std::string> refused;
    const std::vector<std::vector<std::byte>> burst = {
        packet("/tactus/post.drive_db", "f", 3.0),
        packet("/tactus/post.drive_db", "f", 4.0),
        packet("/tactus/post.drive_db", "f", 99.0),
        packet("/tactus/no.such", "i", 1),
        std::vector<std::byte>(5, std::byte{1}),
        packet("/tactus/actuator/2/gain", "f", -6.0),
        packet("/tactus/preset", "s", "four-channel"),
        packet("/tactus/envelope.decay_ms", "f", 321.0)};
    handle_osc_packets(burst, control, [&](const std::string& line) { refused.push_back(line); });
    EXPECT_EQ(refused.size(), 3u);
    for (const auto& line : refused) EXPECT_EQ(line.find('\n'), std::string::npos);
    const Settings now = control.settings();
    Settings four;
    apply_preset_file(four, resolve_preset("four-channel"));
    EXPECT_EQ(now[P::post_drive_db], four[P::post_drive_db]) << "the preset came after";
    EXPECT_EQ(now[P::post_release_ms], 100) << "the command line's --set stays on top";
    EXPECT_EQ(now[P::envelope_decay_ms], 321);
    EXPECT_EQ(now[P::flutter_weight], four[P::flutter_weight]);
    EXPECT_EQ(engine.settings()[P::envelope_decay_ms], 321);
}

// Every message to a parameter's address is answered once the burst is applied, to its sender,
// with the value then in force: a question, a set (the last of the burst), a refused set (the
// value kept); a preset applied is acknowledged with its name; nothing else is answered.
TEST(OscServerHandling, AnswersWithTheValuesInForce) {
    Engine engine;
    LiveControl control(engine, {});
    const std::vector<std::vector<std::byte>> burst = {
        packet("/tactus/post.drive_db", ""),
        packet("/tactus/post.drive_db", "f", 3.0),
        packet("/tactus/envelope.decay_ms", "f", 99999.0),
        packet("/tactus/mapping.frequency.curve", "s", "log"),
        packet("/tactus/trigger", ""),
        packet("/tactus/preset", "s", "nonesuch"),
        packet("/tactus/no.such", ""),
        packet("/tactus/post.drive_db", "f", 4.0)};
    std::vector<std::pair<size_t, OscMessage>> replies;
    std::vector<std::string> refused;
    handle_osc_packets(
        burst, control, [&](const std::string& line) { refused.push_back(line); },
        [&](size_t k, const OscMessage& m) { replies.emplace_back(k, m); });
    EXPECT_EQ(refused.size(), 3u) << "the decay, the preset, the unknown address";
    ASSERT_EQ(replies.size(), 5u);
    const auto number = [&](size_t i) { return replies[i].second.args.at(0).number; };
    EXPECT_EQ(replies[0].first, 0u);
    EXPECT_EQ(replies[0].second.address, "/tactus/post.drive_db");
    EXPECT_EQ(replies[0].second.args.at(0).type, 'f');
    EXPECT_EQ(number(0), 4) << "the value in force once the burst applied";
    EXPECT_EQ(replies[1].first, 1u);
    EXPECT_EQ(number(1), 4);
    EXPECT_EQ(replies[2].second.address, "/tactus/envelope.decay_ms");
    EXPECT_EQ(number(2), Settings{}[P::envelope_decay_ms]) << "refused: the value kept";
    EXPECT_EQ(replies[3].second.args.at(0).type, 's');
    EXPECT_EQ(replies[3].second.args.at(0).text, "log") << "a choice by its name";
    EXPECT_EQ(replies[4].first, 7u);

    replies.clear();
    handle_osc_packets(
        std::vector<std::vector<std::byte>>{packet("/tactus/preset", "s", "four-channel")}, control,
        [](const std::string&) {},
        [&](size_t k, const OscMessage& m) { replies.emplace_back(k, m); });
    ASSERT_EQ(replies.size(), 1u);
    EXPECT_EQ(replies[0].second.address, "/tactus/preset");
    EXPECT_EQ(replies[0].second.args.at(0).text, "four-channel");
    // What goes out is what comes in: the reply decodes to itself.
    const std::vector<OscMessage> decoded = decode_osc_packet(
        encode_osc_message(parameter_reply(P::post_drive_db, control.settings())));
    ASSERT_EQ(decoded.size(), 1u);
    EXPECT_EQ(decoded[0].address, "/tactus/post.drive_db");
    EXPECT_EQ(decoded[0].args.at(0).number, control.settings()[P::post_drive_db]);
}

// The preset file rewritten while running: a good file applies (the --set on top), a file with
// an error keeps the running settings and says why in one line.
class PresetWatching : public test::TempDirTest {};

TEST_F(PresetWatching, ReloadsAndRefuses) {
    const auto preset = dir_ / "mine.toml";
    const auto save = [&](const std::string& text) {  // as editors do: write, then rename
        std::ofstream(dir_ / "mine.toml.new") << text;
        std::filesystem::rename(dir_ / "mine.toml.new", preset);
    };
    save("[envelope]\ndecay_ms = 200\n");
    Engine engine;
    LiveControl control(engine, {"post.release_ms=100"});
    std::mutex mutex;
    std::vector<std::string> lines;
    PresetWatcher watcher(preset, control, [&](const std::string& line) {
        const std::lock_guard lock(mutex);
        lines.push_back(line);
    });
    const auto wait_for = [&](size_t count) {
        for (int i = 0; i < 400 && watcher.reloads() < static_cast<int>(count); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        ASSERT_EQ(watcher.reloads(), static_cast<int>(count));
    };
    save("[envelope]\ndecay_ms = 321\n");
    ASSERT_NO_FATAL_FAILURE(wait_for(1));
    EXPECT_EQ(control.settings()[P::envelope_decay_ms], 321);
    EXPECT_EQ(control.settings()[P::post_release_ms], 100) << "--set stays on top";
    save("[envelope]\ndecay_ms = 99999\n");  // out of range
    ASSERT_NO_FATAL_FAILURE(wait_for(2));
    EXPECT_EQ(control.settings()[P::envelope_decay_ms], 321) << "the running settings kept";
    save("[envelope\n");  // TOML syntax
    ASSERT_NO_FATAL_FAILURE(wait_for(3));
    EXPECT_EQ(control.settings()[P::envelope_decay_ms], 321);
    const std::lock_guard lock(mutex);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_NE(lines[0].find("reloaded"), std::string::npos) << lines[0];
    for (size_t i : {1u, 2u}) {
        EXPECT_NE(lines[i].find("keeping the running settings"), std::string::npos) << lines[i];
        EXPECT_NE(lines[i].find("mine.toml"), std::string::npos) << lines[i];
        EXPECT_EQ(lines[i].find('\n'), std::string::npos) << lines[i];
    }
}

TEST(Endpoint, HostAndPort) {
    EXPECT_EQ(parse_endpoint("9000", "--osc-port", "127.0.0.1").host, "127.0.0.1");
    EXPECT_EQ(parse_endpoint("0.0.0.0:9000", "--osc-port", "127.0.0.1").host, "0.0.0.0");
    EXPECT_EQ(parse_endpoint("0.0.0.0:9000", "--osc-port", "127.0.0.1").port, 9000);
    for (const char* bad : {"", "x", "70000", ":9000", "host:", "host:0"})
        EXPECT_THROW(parse_endpoint(bad, "--osc-port", "127.0.0.1"), std::invalid_argument) << bad;
}

TEST(ChannelList, FromOne) {
    EXPECT_EQ(parse_channel_list("1,3", "--x"), (std::vector<int>{0, 2}));
    EXPECT_EQ(parse_channel_list("2-4", "--x"), (std::vector<int>{1, 2, 3}));
    for (const char* bad : {"", "0", "1,1", "3-1", "a", "1,,2", "2000"})
        EXPECT_THROW(parse_channel_list(bad, "--x"), std::invalid_argument) << bad;
}

TEST(ChannelList, DeviceAndChannel) {
    using Pair = std::pair<std::string, int>;
    EXPECT_EQ(parse_device_channel("system:2", "--x", false), (Pair{"system", 1}));
    EXPECT_EQ(parse_device_channel("hw:0:3", "--x", true), (Pair{"hw:0", 2}));
    EXPECT_EQ(parse_device_channel("Built-in Audio", "--x", true), (Pair{"Built-in Audio", -1}));
    EXPECT_EQ(parse_device_channel("dev:front", "--x", true), (Pair{"dev:front", -1}));
    for (const char* bad : {"system", "system:", ":2", "dev:front", "dev:1,2"})
        EXPECT_THROW(parse_device_channel(bad, "--x", false), std::invalid_argument) << bad;
    EXPECT_THROW(parse_device_channel("system:0", "--x", true), std::invalid_argument);
}

TEST(StatusLine, SaysEveryMeter) {
    const std::string s = status_text(
        {.input_peak = 0.5f, .output_peak = 0, .load = 0.25, .xruns = 3, .frames = 0}, 2.0, 9, 4.4);
    EXPECT_NE(s.find("in   -6.0 dBFS"), std::string::npos) << s;
    EXPECT_NE(s.find("out   -inf dBFS"), std::string::npos) << s;
    EXPECT_NE(s.find("onsets  4.5/s"), std::string::npos) << s;
    EXPECT_NE(s.find("load  25 %"), std::string::npos) << s;
    EXPECT_NE(s.find("xruns 3"), std::string::npos) << s;
    EXPECT_NE(s.find("latency 4.4 ms"), std::string::npos) << s;
}

}  // namespace
}  // namespace tactus::live
