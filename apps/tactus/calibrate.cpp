// tactus calibrate --output DEV:CH --input DEV:CH [-o PROFILE.toml]: measures the actuator on
// one output channel with a sensor (accelerometer, contact microphone) on one input channel, by
// Farina's swept sine (actuator/calibration.hpp), and writes an actuator profile that --actuator
// loads. The shipped profiles are typical values; this one is the actuator as mounted.
#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <thread>

#include "actuator_option.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "helper_commands.hpp"
#include "live/channel_list.hpp"
#include "live/device_stream.hpp"
#include "live/sweep_recorder.hpp"
#include "tactus/actuator/calibration.hpp"
#include "tactus/core/units.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus::cli {
namespace {

constexpr double kSweepTailS = 1.0;     // recorded after the sweep: the device delay and the decay
constexpr double kTimeoutMarginS = 30;  // a busy machine, a slow server

struct CalibrateOptions {
    std::string backend, output, input, profile_out;
    std::string base;
    double rate_hz = 0, low_hz = 20, high_hz = 2000, seconds = 5, level_db = -6;
    int block = 256;
    bool force = false;
};

void calibrate(const CalibrateOptions& o) {
    if (o.profile_out.empty()) throw std::runtime_error("calibrate: give -o PROFILE.toml");
    check_output({}, o.profile_out, o.force);  // no input file to protect
    std::optional<ActuatorProfile> base;
    if (!o.base.empty()) base = load_actuator(resolve_actuator(o.base));
    const auto [out_device, out_channel] = live::parse_device_channel(o.output, "--output", false);
    const auto [in_device, in_channel] = live::parse_device_channel(o.input, "--input", false);

    live::StreamRequest request;
    request.backend = o.backend.empty() ? RtAudio::UNSPECIFIED : live::backend_named(o.backend);
    request.output_device = out_device;
    request.output_channels = out_channel + 1;
    request.input_device = in_device;
    request.input_channels = 1;
    request.input_first_channel = in_channel;
    request.sample_rate_hz = o.rate_hz;
    request.block_frames = o.block;
    request.client_name = "tactus-calibrate";
    live::DeviceStream stream(request);
    const double rate_hz = stream.sample_rate_hz();

    const SweepSpec spec{.sample_rate_hz = rate_hz,
                         .low_hz = o.low_hz,
                         .high_hz = o.high_hz,
                         .seconds = o.seconds,
                         .level = db_to_gain(o.level_db)};
    live::SweepRecorder recorder(exponential_sweep(spec), out_channel + 1, out_channel,
                                 static_cast<int>(kSweepTailS * rate_hz));
    std::cerr << fmt::format(
        "tactus: calibrate: a {:g} s sweep {:g}-{:g} Hz at {:g} dBFS on {} channel {}, recording "
        "{} channel {}\n",
        o.seconds, o.low_hz, o.high_hz, o.level_db, out_device, out_channel + 1, in_device,
        in_channel + 1);
    stream.start(recorder);
    recorder.begin();
    const auto give_up = std::chrono::steady_clock::now() +
                         std::chrono::duration<double>(o.seconds + kSweepTailS + kTimeoutMarginS);
    while (!recorder.done()) {
        if (stream.lost()) throw std::runtime_error("calibrate: the audio device stopped");
        if (std::chrono::steady_clock::now() > give_up)
            throw std::runtime_error("calibrate: the device did not run the sweep in time");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    stream.stop();
    if (recorder.xruns() > 0)
        std::cerr << fmt::format(
            "tactus: warning: {} xruns during the sweep: measure again if "
            "the response looks wrong\n",
            recorder.xruns());
    const auto measured = measure_response(recorder.sweep(), recorder.recorded(), spec);
    ActuatorProfile profile = measured_profile(measured, base ? &*base : nullptr);
    profile.name = std::filesystem::path(o.profile_out).stem().string();
    profile.description =
        fmt::format("measured by tactus calibrate: {}:{} -> {}:{}, {:g}-{:g} Hz", out_device,
                    out_channel + 1, in_device, in_channel + 1, o.low_hz, o.high_hz);
    const std::string text = actuator_text(
        profile, fmt::format("An actuator profile measured with a swept sine (Farina's method): "
                             "the points are\nthe response relative to reference_hz{}.",
                             base ? fmt::format("; other values from {}", o.base) : ""));
    parse_actuator(text, o.profile_out);  // what --actuator will read
    TextOutput output(o.profile_out);
    output.stream() << text;
    output.commit();
    std::cerr << fmt::format("tactus: {}: peak at {:g} Hz, band {:g}-{:g} Hz, {} points\n",
                             o.profile_out, profile.reference_hz, profile.band_low_hz,
                             profile.band_high_hz, profile.points.size());
}

}  // namespace

void add_calibrate(CLI::App& app) {
    auto o = std::make_shared<CalibrateOptions>();
    CLI::App* command = app.add_subcommand(kCalibrateCommand.name, kCalibrateCommand.description);
    command->add_option("--output", o->output, "the actuator: DEV:CH (CH from 1)")->required();
    command->add_option("--input", o->input, "the sensor on it: DEV:CH")->required();
    command->add_option("-o,--profile", o->profile_out, "actuator profile to write (.toml)")
        ->required();
    command->add_option("--backend", o->backend, "jack, alsa or pulse");
    command->add_option("--like", o->base,
                        "take type, displacement, drive, reference and band from this profile");
    command->add_option("--rate", o->rate_hz, "sample rate, Hz (default: the device's)");
    command->add_option("--low-hz", o->low_hz, "sweep start, Hz")->capture_default_str();
    command->add_option("--high-hz", o->high_hz, "sweep end, Hz")->capture_default_str();
    command->add_option("--seconds", o->seconds, "sweep length")->capture_default_str();
    command->add_option("--level-db", o->level_db, "sweep level, dBFS")
        ->check(CLI::Range(-60.0, 0.0))
        ->capture_default_str();
    command->add_option("--block", o->block, "frames per device block")
        ->check(CLI::Range(16, Engine::kMaxBlock))
        ->capture_default_str();
    add_force_option(*command, o->force);
    command->callback([o] { calibrate(*o); });
}

}  // namespace tactus::cli
