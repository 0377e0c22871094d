// tactus live: sound and vibration together on audio devices (paper §6: the Tactilicious Flute
// Display is a real-time display). Two sources, the paper's two display modes: an instrument's
// input (--input), or a player (--play) sending the sound to --sound-channels and the vibration
// to --actuator-channels. OSC control and monitoring, the preset file watched, a status line.
// The pieces live in live/; this file wires them together on the main thread.
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>
#include <utility>

#include "actuator_option.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "helper_commands.hpp"
#include "layout_option.hpp"
#include "live/channel_list.hpp"
#include "live/console.hpp"
#include "live/device_stream.hpp"
#include "live/frame_monitor.hpp"
#include "live/live_callback.hpp"
#include "live/live_control.hpp"
#include "live/osc_server.hpp"
#include "live/player.hpp"
#include "live/preset_watcher.hpp"
#include "live/reconnector.hpp"
#include "live/status_line.hpp"
#include "live/sync_delay.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/preset.hpp"

namespace tactus::cli {
namespace {

constexpr double kDefaultOscRateHz = 100;
constexpr auto kTick = std::chrono::milliseconds(50);   // the main loop's pace
constexpr double kStatusPeriodS = 0.5;                  // the status line's redraw
constexpr auto kRetryPeriod = std::chrono::seconds(1);  // a lost device's retries
// Played on after the player's last frame: the engine's latency and more.
constexpr double kPlayerTailS = 0.25;

std::atomic<bool> g_stop{false};
extern "C" void request_stop(int) {
    g_stop = true;
}

struct LiveOptions {
    std::string backend, input, output;
    std::string actuator_channels = "1", sound_channels;
    std::string layout;
    std::vector<std::string> play;
    bool loop = false, sync = false;
    std::vector<std::string> actuators;       // one for all, or one per actuator channel
    std::vector<double> gains_db, delays_ms;  // the same
    double rate_hz = 0;
    int block = 256;
    bool block_given = false;  // --block on the command line
    std::string osc_port, osc_send;
    double osc_rate_hz = kDefaultOscRateHz;
    double duration_s = 0;
    PipelineOptions pipeline;
};

// One value for every actuator, or one each; `what` names the option.
template <typename T>
T for_actuator(const std::vector<T>& values, size_t actuator, size_t actuators, const char* what,
               T otherwise) {
    if (values.empty()) return otherwise;
    if (values.size() != 1 && values.size() != actuators)
        throw std::runtime_error(
            fmt::format("{}: give one value for all {} actuators or one each", what, actuators));
    return values[values.size() == 1 ? 0 : actuator];
}

// The paper drives every actuator with one signal: each output here has its own profile, trim
// and delay (the engine's ActuatorOutput), the same by default.
std::vector<ActuatorOutput> actuator_outputs(const LiveOptions& o, const Settings& settings,
                                             const live::Routing& routing) {
    const size_t n = routing.actuator_channels.size();
    std::vector<ActuatorOutput> outputs(n);
    for (size_t a = 0; a < n; ++a) {
        const std::string name = for_actuator(o.actuators, a, n, "--actuator", std::string());
        if (!name.empty()) outputs[a].profile = load_actuator_for(name, settings);
        outputs[a].gain_db = for_actuator(o.gains_db, a, n, "--actuator-gain-db", 0.0);
        outputs[a].delay_ms = for_actuator(o.delays_ms, a, n, "--actuator-delay-ms", 0.0);
        try {
            outputs[a].check(static_cast<int>(a));
        } catch (const std::invalid_argument& e) {
            throw std::runtime_error(e.what());
        }
    }
    return outputs;
}

live::StreamRequest stream_request(const LiveOptions& o, const live::Routing& routing,
                                   double rate_hz) {
    live::StreamRequest r;
    r.backend = o.backend.empty() ? RtAudio::UNSPECIFIED : live::backend_named(o.backend);
    r.output_device = o.output;
    r.output_channels = routing.device_outputs;
    if (!o.input.empty()) {
        const auto [device, channel] = live::parse_device_channel(o.input, "--input", true);
        r.input_device = device;
        r.input_channels = channel < 0 ? -1 : 1;
        r.input_first_channel = std::max(channel, 0);
    }
    r.sample_rate_hz = rate_hz;
    r.rate_required = o.rate_hz > 0;
    r.block_frames = o.block;
    return r;
}

void live_run(const LiveOptions& o) {
    const Settings settings = o.pipeline.resolve();
    if (o.play.empty() == o.input.empty())
        throw std::runtime_error("live: give either --input DEV[:CH] or --play FILE...");
    for (const auto& file : o.play) check_input(file, false);
    if (o.loop && o.play.empty()) throw std::runtime_error("live: --loop plays files: give --play");
    if (o.sync && o.play.empty())
        throw std::runtime_error("live: --sync delays the sound of --play");

    live::Routing routing;
    std::optional<Layout> layout;
    if (!o.layout.empty()) {  // the layout's channels; its sound channels carry --play's
        layout = load_layout(resolve_layout(o.layout));
        routing.actuator_channels.resize(layout->outputs.size());
        for (size_t k = 0; k < layout->outputs.size(); ++k)
            routing.actuator_channels[k] = layout->outputs[k].channel;
        if (!o.play.empty()) routing.sound_channels = layout->sound_channels;
    } else {
        routing.actuator_channels =
            live::parse_channel_list(o.actuator_channels, "--actuator-channels");
    }
    if (!o.sound_channels.empty()) {
        if (o.play.empty())
            throw std::runtime_error("live: --sound-channels carry the sound of --play");
        routing.sound_channels = live::parse_channel_list(o.sound_channels, "--sound-channels");
        for (int c : routing.sound_channels)
            if (std::find(routing.actuator_channels.begin(), routing.actuator_channels.end(), c) !=
                routing.actuator_channels.end())
                throw std::runtime_error(
                    fmt::format("live: channel {} is both an actuator and a sound channel", c + 1));
    }
    for (const auto* list : {&routing.actuator_channels, &routing.sound_channels})
        for (int c : *list) routing.device_outputs = std::max(routing.device_outputs, c + 1);
    if (static_cast<int>(routing.actuator_channels.size()) > Engine::kMaxActuators)
        throw std::runtime_error(
            fmt::format("--actuator-channels: at most {} actuators", Engine::kMaxActuators));

    const std::vector<ActuatorOutput> outputs =
        layout ? layout_outputs(*layout, settings) : actuator_outputs(o, settings, routing);
    std::optional<live::OscEndpoint> osc_in, osc_out;
    if (!o.osc_port.empty()) osc_in = live::parse_endpoint(o.osc_port, "--osc-port", "127.0.0.1");
    if (!o.osc_send.empty()) osc_out = live::parse_endpoint(o.osc_send, "--osc-send", "127.0.0.1");

    // The device first: its rate is the engine's (JACK's is the server's). Without --rate it is
    // asked for the first file's rate; the player converts the files at another one.
    double rate_hz = o.rate_hz;
    if (rate_hz <= 0 && !o.play.empty()) rate_hz = live::Player::sample_rate_of(o.play[0]);
    const live::StreamRequest request = stream_request(o, routing, rate_hz);
    auto stream = std::make_unique<live::DeviceStream>(request);
    rate_hz = stream->sample_rate_hz();
    live::Console console(std::cerr, ::isatty(STDERR_FILENO) == 1);
    if (o.block_given && stream->block_frames() != o.block)
        console.message(fmt::format("--block {}: {} {} frames a block; using {}", o.block,
                                    stream->runs(), stream->block_frames(),
                                    stream->block_frames()));

    std::optional<live::Player> player;
    if (!o.play.empty()) {
        player.emplace(std::vector<std::filesystem::path>(o.play.begin(), o.play.end()), rate_hz,
                       o.loop);
        for (const std::string& line : player->conversions()) console.message(line);
    }
    routing.device_inputs = player ? 0 : stream->input_channels();

    Engine engine(settings);
    engine.set_actuators(outputs);
    engine.enable_frame_queue();
    engine.prepare({.sample_rate_hz = rate_hz,
                    .max_block = std::min(Engine::kMaxBlock, std::max(stream->block_frames(), 16)),
                    .channels = player ? player->channels() : routing.device_inputs});
    live::VibrationDelay onset_to_pulse(settings, rate_hz, outputs[0].profile);
    live::LiveCallback callback(engine, player ? &*player : nullptr, routing,
                                o.sync ? onset_to_pulse.samples() : live::kNoSync);

    live::LiveControl control(engine, o.pipeline.assignments, [&engine](const std::string& name) {
        return load_actuator_for(name, engine.settings());  // its warnings on the console
    });
    const auto report = [&console](const std::string& line) { console.message(line); };
    std::optional<live::OscServer> server;
    if (osc_in) server.emplace(*osc_in, control, report);
    std::optional<live::OscSender> sender;
    if (osc_out) sender.emplace(*osc_out);
    live::FrameMonitor monitor(engine, sender ? &*sender : nullptr, o.osc_rate_hz);
    live::PresetWatcher watcher(resolve_preset(o.pipeline.preset), control, report);

    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    stream->start(callback);  // the device's ports are connected when it returns
    callback.begin();
    if (server) server->start();

    const long device_frames = stream->device_latency_frames();
    const auto ms = [&](double frames) { return 1000.0 * frames / rate_hz; };
    const auto latency_ms = [&] {
        return ms(static_cast<double>(device_frames + onset_to_pulse.samples()));
    };
    // The algorithmic part and --sync's delay, at the start and after each change of them.
    const auto latency_text = [&] {
        const int frames = onset_to_pulse.samples();
        return fmt::format(
            "latency {:.2f} ms: device {} frames ({:.2f} ms) + algorithmic {} frames ({:.2f} ms: "
            "onset to pulse, of which look-ahead {} frames){}",
            latency_ms(), device_frames, ms(static_cast<double>(device_frames)), frames, ms(frames),
            engine.latency(),
            o.sync ? fmt::format("; sound delayed {} frames (--sync)", frames) : "");
    };
    console.message(fmt::format(
        "live on {} at {:g} Hz, {} frames a block, {} actuator(s){}{}", stream->output_name(),
        rate_hz, stream->block_frames(), routing.actuator_channels.size(),
        server ? fmt::format(", OSC on port {}", server->port()) : "",
        sender ? fmt::format(", OSC to {}:{}", osc_out->host, osc_out->port) : ""));
    console.message(latency_text());

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto last_status = start;
    std::optional<Clock::time_point> finished_at;
    int64_t onsets_before = 0;
    std::optional<live::Reconnector> reconnector;  // while the device is lost
    while (!g_stop) {
        std::this_thread::sleep_for(kTick);
        const auto now = Clock::now();
        const double elapsed_s = std::chrono::duration<double>(now - start).count();
        if (o.duration_s > 0 && elapsed_s >= o.duration_s) break;
        if (onset_to_pulse.follow(control.settings(), elapsed_s)) {  // the settings changed it
            callback.set_sync_delay_samples(onset_to_pulse.samples());
            console.message("new settings: " + latency_text());
        }
        if (player && player->finished()) {
            if (!finished_at) finished_at = now;
            if (now - *finished_at >= std::chrono::duration<double>(
                                          kPlayerTailS + 4.0 * onset_to_pulse.samples() / rate_hz))
                break;
        }
        if (!reconnector && stream->lost()) {
            console.message(fmt::format(
                "the audio device stopped after {:.2f} s of audio; retrying every second until it "
                "returns (Ctrl-C stops)",
                callback.frames() / rate_hz));
            reconnector.emplace(
                std::exchange(stream, nullptr),  // empty until the device returns
                [&] {
                    auto again =
                        std::make_unique<live::DeviceStream>(stream_request(o, routing, rate_hz));
                    if (again->sample_rate_hz() != rate_hz)
                        throw std::runtime_error("the device came back at another rate");
                    again->start(callback);
                    return again;
                },
                kRetryPeriod);
        }
        if (reconnector) {
            stream = reconnector->take();
            if (!stream) continue;
            reconnector.reset();
            console.message("the audio device is back");
        }
        const double since_status_s = std::chrono::duration<double>(now - last_status).count();
        if (console.terminal() && since_status_s >= kStatusPeriodS) {
            const int64_t onsets = monitor.onsets();
            console.status(live::status_text(callback.take_meters(), since_status_s,
                                             onsets - onsets_before, latency_ms()));
            onsets_before = onsets;
            last_status = now;
        }
    }
    reconnector.reset();
    if (stream) stream->stop();
    const live::Meters meters = callback.take_meters();
    console.keep_status();
    console.message(fmt::format("stopped after {:.2f} s of audio, {} onsets, {} xruns",
                                meters.frames / rate_hz, monitor.onsets(), meters.xruns));
}

}  // namespace

void add_live(CLI::App& app) {
    auto o = std::make_shared<LiveOptions>();
    CLI::App* command = app.add_subcommand(kLiveCommand.name, kLiveCommand.description);
    command->add_option("--backend", o->backend,
                        "jack, alsa or pulse (default: the first with devices)");
    command->add_option("--input,-i", o->input,
                        "instrument input: DEV (all its channels, downmixed) or DEV:CH");
    command->add_option("--output", o->output, "output device (default: the backend's default)");
    command
        ->add_option("--actuator-channels", o->actuator_channels,
                     "output channels of the actuators, from 1: 1,2 or 1-4 (one actuator each, "
                     "the same signal)")
        ->capture_default_str();
    CLI::Option* sound =
        command->add_option("--sound-channels", o->sound_channels,
                            "output channels of the sound of --play (its channels in turn)");
    command->add_option("--play", o->play, "audio files played as sound and vibration")
        ->type_name("FILE");
    command->add_flag("--loop", o->loop, "play the files again and again");
    command->add_flag("--sync", o->sync,
                      "delay the sound by the vibration's latency so onsets line up");
    command
        ->add_option("--actuator,-a", o->actuators,
                     "actuator profile (name in actuators/ or FILE.toml): one for every "
                     "actuator, or one each")
        ->delimiter(',');
    command
        ->add_option("--actuator-gain-db", o->gains_db,
                     "trim after the limiter, dB (<= 0): one for all, or one each")
        ->delimiter(',');
    command->add_option("--actuator-delay-ms", o->delays_ms, "delay, ms: one for all, or one each")
        ->delimiter(',');
    command
        ->add_option("--rate", o->rate_hz,
                     "sample rate, Hz (default: the file's if the device runs at it, else the "
                     "device's: files at another rate are converted)")
        ->check(CLI::Range(Engine::kMinSampleRateHz, Engine::kMaxSampleRateHz));
    CLI::Option* block =
        command->add_option("--block", o->block, "frames per device block (JACK: the server's)")
            ->check(CLI::Range(16, Engine::kMaxBlock))
            ->capture_default_str();
    command->add_option("--osc-port", o->osc_port,
                        "listen for OSC control on [HOST:]PORT (HOST: 127.0.0.1 unless named)");
    command->add_option("--osc-send", o->osc_send, "send features and vibration to HOST:PORT");
    command->add_option("--osc-rate", o->osc_rate_hz, "rate of /tactus/features and /vibration, Hz")
        ->check(CLI::Range(1.0, 1000.0))
        ->capture_default_str();
    command
        ->add_option("--duration", o->duration_s,
                     "stop after this many seconds (default: Ctrl-C, or the end of --play)")
        ->check(CLI::PositiveNumber);
    CLI::Option* layout = add_layout_option(*command, o->layout);
    for (const char* name :
         {"--actuator-channels", "--actuator", "--actuator-gain-db", "--actuator-delay-ms"})
        layout->excludes(command->get_option(name));
    layout->excludes(sound);
    o->pipeline.add_to(*command);
    command->callback([o, block] {
        o->block_given = block->count() > 0;
        live_run(*o);
    });
}

}  // namespace tactus::cli
