// tactus render IN -o OUT.wav: audio file -> vibration file (float WAV, N identical channels).
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "common.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/audio_writer.hpp"

namespace tactus::cli {
namespace {

struct RenderOptions {
    std::string input, output;
    int channels = 1;
    bool force = false;
    PipelineOptions pipeline;
};

class OnsetCounter final : public FrameObserver {
  public:
    void on_frame(const Features&, const ControlFrame& control) noexcept override {
        onsets += control.trigger;
    }
    int onsets = 0;
};

void render(const RenderOptions& o) {
    const Settings settings = o.pipeline.resolve();
    check_output(o.input, o.output, o.force);
    Engine engine(settings);
    OnsetCounter counter;
    engine.set_observer(&counter);
    std::optional<AudioWriter> writer;  // opened at the input's sample rate
    float peak = 0.0f;
    const RunSummary summary = run_with_progress(
        o.input, engine, "render",
        {.on_output =
             [&](const float* v, int n) {
                 for (int i = 0; i < n; ++i) peak = std::max(peak, std::abs(v[i]));
                 writer->write(v, n);
             },
         .on_start = [&](double sample_rate_hz,
                         int) { writer.emplace(o.output, sample_rate_hz, o.channels); }});
    writer->commit();
    std::cerr << fmt::format(
        "{}: {:.2f} s at {:g} Hz, {} pulses, peak {:.1f} dBFS, {} channel(s)\n", o.output,
        summary.frames / summary.sample_rate_hz, summary.sample_rate_hz, counter.onsets,
        peak > 0 ? 20 * std::log10(peak) : -INFINITY, o.channels);
}

}  // namespace

void add_render(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand("render", "render the vibration for an audio file");
    command->add_option("input", options->input, "audio file (anything libsndfile reads)")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", options->output, "vibration file to write (.wav)")
        ->required();
    command->add_option("--channels,-c", options->channels, "identical actuator channels")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    add_force_option(*command, options->force);
    options->pipeline.add_to(*command);
    command->callback([options] { render(*options); });
}

}  // namespace tactus::cli
