// tactus render IN... (-o OUT | -O DIR) [-j N]: audio files -> vibration files (N identical
// channels, or a layout's channels: each output playing its route, the sound on its sound
// channels; the container the output's extension names, the vibration's tail included, how it
// was made in the file's comment). Several inputs are rendered in parallel, one file per
// worker, each with its own Engine.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <thread>

#include "actuator_option.hpp"
#include "batch_plan.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "global_options.hpp"
#include "layout_option.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/audio_writer.hpp"
#include "tactus/io/layout_frames.hpp"
#include "tactus/io/render_info.hpp"
#include "tactus/io/temporary_path.hpp"
#include "unfelt_sound.hpp"

namespace tactus::cli {
namespace {

constexpr const char* kOutputSuffix = ".vibration.wav";

struct RenderOptions {
    BatchOptions batch;
    SampleFormat sample_format = SampleFormat::automatic;
    int channels = 1;
    std::string actuator;
    std::string layout;
    PipelineOptions pipeline;
};

// What each render writes: N identical outputs (--channels, --actuator) or a layout's.
struct Outputs {
    std::vector<ActuatorOutput> engine;
    std::optional<Layout> layout;
    int file_channels() const {
        return layout ? layout->channels : static_cast<int>(engine.size());
    }
};

using Job = BatchJob;

// The pulses a render triggers (for the summary: each lane's, so each output's) and the sound
// it left unfelt (the warnings that audible input gave no vibration, in whole or for a long
// stretch).
class RenderStats final : public FrameObserver {
  public:
    explicit RenderStats(const Settings& settings) : unfelt(settings) {}
    void on_frame(const Features& features, const ControlFrame&) noexcept override {
        unfelt.on_loudness(features.loudness_db);
    }
    void on_lane_frame(int lane, const ControlFrame& control) noexcept override {
        lane_pulses[static_cast<size_t>(lane)] += control.trigger;
    }
    FeatureSet reads() const noexcept override {
        return {.loudness = true, .spectrum = false, .pitch = false};
    }
    std::array<int, Engine::kMaxActuators> lane_pulses{};
    UnfeltSound unfelt;
};

// Where each input's vibration goes (batch_plan.hpp: -o for one input, with -O the input's
// folders mirrored, DIR/.../<stem>.vibration.wav), each in a container libsndfile writes; all
// refused before any audio is read.
std::vector<Job> plan(const RenderOptions& o) {
    size_t skipped = 0;
    std::vector<Job> jobs = plan_batch(o.batch, kOutputSuffix, skipped);
    for (const Job& job : jobs) writable_sound_format(job.output, o.sample_format);
    return jobs;
}

// Renders one file; returns its one-line summary. On failure the output is not written.
std::string render_one(const Job& job, const Settings& settings, const Outputs& outputs,
                       SampleFormat sample_format, const RenderInfo& how, RunAnalysis analysis,
                       const std::function<void(int64_t done, int64_t total)>& on_progress) {
    Engine engine(settings);
    engine.set_actuators(outputs.engine);
    RenderStats stats(settings);
    engine.set_observer(&stats);
    const int channels = outputs.file_channels();
    std::optional<AudioWriter> writer;  // opened at the input's sample rate
    std::optional<LayoutFrames> frames;
    int input_channels = 1;
    const auto write = [&](const float* const* v, int n) {
        stats.unfelt.on_output(v, engine.actuators(), n);
        writer->write(frames ? frames->compose(v, n) : v, n);
    };
    const auto sound = [&](const float* const* in, int n) {
        if (frames) frames->set_sound(in, input_channels, n);
    };
    RenderInfo info = how;
    info.source = job.input.filename().string();
    const auto open = [&](double sample_rate_hz, int input) {
        input_channels = input;
        if (outputs.layout) frames.emplace(*outputs.layout, kStreamBlockFrames);
        writer.emplace(job.output, sample_rate_hz, channels, sample_format,
                       SoundTags{.software = "tactus " + info.version, .comment = info.comment()});
    };
    // The vibration rings out after the input: a short sound keeps its whole pulse.
    const RunSummary summary = run_file(
        job.input, engine,
        {.on_output = write, .on_progress = on_progress, .on_start = open, .on_input = sound},
        RunTail::ring_out, analysis);
    writer->commit();
    if (const std::string warning =
            stats.unfelt.warning(job.input.string(), summary.sample_rate_hz);
        !warning.empty())
        note(warning);
    // The pulses: the one count of outputs alike, else each layout output's.
    std::string pulses = fmt::format("{} pulses", stats.lane_pulses[0]);
    if (outputs.layout && engine.lanes() > 1) {
        pulses = "pulses";
        for (int k = 0; k < engine.actuators(); ++k)
            pulses += fmt::format("{} {} {}", k ? "," : "", outputs.layout->outputs[k].name,
                                  stats.lane_pulses[static_cast<size_t>(engine.lane_of(k))]);
    }
    return fmt::format(
        "{}: {:.2f} s at {:g} Hz, {}, peak {:.1f} dBFS, {} channel(s)", job.output.string(),
        (summary.frames + summary.tail_frames) / summary.sample_rate_hz, summary.sample_rate_hz,
        pulses, stats.unfelt.peak() > 0 ? 20 * std::log10(stats.unfelt.peak()) : -INFINITY,
        channels);
}

// Frames in all inputs, for the progress bar (unreadable inputs count 0 and fail later).
int64_t total_frames(const std::vector<Job>& jobs) {
    int64_t total = 0;
    for (const Job& job : jobs) try {
            total += std::max<int64_t>(0, AudioReader(job.input).frames());
        } catch (const std::exception&) {
        }
    return total;
}

void render(const RenderOptions& o) {
    const Settings settings = o.pipeline.resolve();
    const std::vector<Job> jobs = plan(o);
    Outputs outputs;
    std::string actuator_name;
    if (!o.layout.empty()) {
        outputs.layout = load_layout(resolve_layout(o.layout));
        outputs.engine = layout_outputs(*outputs.layout, settings);
    } else {
        std::optional<ActuatorProfile> actuator;
        if (!o.actuator.empty()) actuator = load_actuator_for(o.actuator, settings);
        if (actuator) actuator_name = actuator->name;
        outputs.engine.assign(static_cast<size_t>(o.channels), ActuatorOutput{.profile = actuator});
    }
    RenderInfo how = o.pipeline.render_info({}, actuator_name);
    how.layout = o.layout;
    // One file at a time: its analysis on a thread of its own; several: a file per core.
    const RunAnalysis analysis =
        std::min<size_t>(jobs.size(), static_cast<size_t>(o.batch.jobs)) > 1 ? RunAnalysis::engine
                                                                             : RunAnalysis::ahead;
    run_jobs(
        o.batch, jobs,
        [&](const Job& job, const AddFrames& add_frames) {
            int64_t reported = 0;
            return render_one(job, settings, outputs, o.sample_format, how, analysis,
                              [&](int64_t done, int64_t) {
                                  add_frames(done - reported);
                                  reported = done;
                              });
        },
        [&] { return total_frames(jobs); });
}

}  // namespace

void add_render(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand("render", "render the vibration for audio files");
    options->batch.output_needed = true;
    options->batch.add_to(*command,
                          "vibration file to write, one input: its extension names the format (" +
                              writable_sound_extensions() + "); - writes WAV to stdout",
                          kOutputSuffix);
    command
        ->add_option("--sample-format", options->sample_format,
                     "16, 24 (bit integer) or float (default: float; FLAC 24; none for .ogg/.mp3)")
        ->transform(CLI::CheckedTransformer(
            std::map<std::string, SampleFormat>{{"16", SampleFormat::pcm16},
                                                {"24", SampleFormat::pcm24},
                                                {"float", SampleFormat::float32}}));
    CLI::Option* channels =
        command->add_option("--channels,-c", options->channels, "identical actuator channels")
            ->check(CLI::Range(1, 64))
            ->capture_default_str();
    add_actuator_option(*command, options->actuator,
                        "actuator profile (name in actuators/ or FILE.toml): compensate its "
                        "response, respect its max drive, warn about what it cannot do");
    add_layout_option(*command, options->layout)
        ->excludes(channels)
        ->excludes(command->get_option("--actuator"));
    options->pipeline.add_to(*command);
    command->callback([options] { render(*options); });
}

}  // namespace tactus::cli
