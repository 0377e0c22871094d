// tactus render IN... (-o OUT.wav | -O DIR) [-j N]: audio files -> vibration files (float WAV, N
// identical channels). Several inputs are rendered in parallel, one file per worker, each with
// its own Engine.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <thread>

#include "actuator_option.hpp"
#include "batch.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/audio_writer.hpp"
#include "tactus/io/temporary_path.hpp"

namespace tactus::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kOutputSuffix = ".vibration.wav";

struct RenderOptions {
    std::vector<std::string> inputs;
    std::string output, output_dir;
    int channels = 1;
    int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::string actuator;
    bool force = false;
    PipelineOptions pipeline;
};

struct Job {
    fs::path input, output;
};

// The pulses a render triggers and the loudest its input got (for the summary and the warning
// that audible input gave no vibration).
class RenderStats final : public FrameObserver {
  public:
    void on_frame(const Features& features, const ControlFrame& control) noexcept override {
        onsets += control.trigger;
        loudest_db = std::max(loudest_db, features.loudness_db);
    }
    FeatureSet reads() const noexcept override {
        return {.loudness = true, .spectrum = false, .pitch = false};
    }
    int onsets = 0;
    double loudest_db = -INFINITY;
};

// Where each input's vibration goes: -o for one input, DIR/<stem>.vibration.wav with -O. Refuses
// (before any audio is read) an output that is its input, that two inputs would share, or that
// exists already (unless --force).
std::vector<Job> plan(const RenderOptions& o) {
    if (o.output.empty() == o.output_dir.empty())
        throw std::runtime_error("render: give either -o FILE (one input) or -O DIR");
    if (!o.output.empty() && o.inputs.size() > 1)
        throw std::runtime_error(fmt::format(
            "render: -o names one output but {} inputs were given; use -O DIR", o.inputs.size()));
    std::vector<Job> jobs;
    std::map<fs::path, fs::path> input_of_output;
    for (const fs::path input : o.inputs) {
        const fs::path output =
            o.output.empty() ? fs::path(o.output_dir) / (input.stem().string() + kOutputSuffix)
                             : fs::path(o.output);
        if (const auto [it, added] = input_of_output.emplace(output, input); !added)
            throw std::runtime_error(fmt::format("{}: both {} and {} would write it",
                                                 output.string(), it->second.string(),
                                                 input.string()));
        if (o.output_dir.empty() || fs::is_directory(o.output_dir))
            check_output(input, output, o.force);
        else
            refuse_overwriting_input(input, output);  // DIR is made below: it holds nothing yet
        jobs.push_back({input, output});
    }
    return jobs;
}

// Renders one file; returns its one-line summary. On failure the output is not written.
std::string render_one(const Job& job, const Settings& settings,
                       const std::optional<ActuatorProfile>& actuator, int channels,
                       const std::function<void(int64_t done, int64_t total)>& on_progress) {
    Engine engine(settings);
    engine.set_actuators(std::vector<ActuatorOutput>(static_cast<size_t>(channels),
                                                     ActuatorOutput{.profile = actuator}));
    RenderStats stats;
    engine.set_observer(&stats);
    std::optional<AudioWriter> writer;  // opened at the input's sample rate
    float peak = 0.0f;
    const auto write = [&](const float* const* v, int n) {
        for (int c = 0; c < channels; ++c)
            for (int i = 0; i < n; ++i) peak = std::max(peak, std::abs(v[c][i]));
        writer->write(v, n);
    };
    const auto open = [&](double sample_rate_hz, int) {
        writer.emplace(job.output, sample_rate_hz, channels);
    };
    const RunSummary summary = run_file(
        job.input, engine, {.on_output = write, .on_progress = on_progress, .on_start = open});
    writer->commit();
    // A drone or a tone that fades in has no onset: a preset that pulses only at onsets leaves it
    // silent. Say so rather than hand back digital silence without a word.
    if (peak == 0 && stats.loudest_db > settings[P::mapping_gate_db])
        std::cerr << fmt::format(
            "tactus: warning: {}: the input is audible (loudness up to {:.0f} dB) but gave no "
            "vibration: it has no onset for the pulses; for sustained sounds try --preset "
            "sustained\n",
            job.input.string(), stats.loudest_db);
    return fmt::format("{}: {:.2f} s at {:g} Hz, {} pulses, peak {:.1f} dBFS, {} channel(s)",
                       job.output.string(), summary.frames / summary.sample_rate_hz,
                       summary.sample_rate_hz, stats.onsets,
                       peak > 0 ? 20 * std::log10(peak) : -INFINITY, channels);
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
    std::optional<ActuatorProfile> actuator;
    if (!o.actuator.empty()) actuator = load_actuator_for(o.actuator, settings);
    if (std::error_code error; !o.output_dir.empty() && !fs::is_directory(o.output_dir) &&
                               !fs::create_directories(o.output_dir, error))
        throw std::runtime_error(fmt::format("{}: cannot create the output directory: {}",
                                             o.output_dir, error.message()));
    std::vector<std::string> summaries(jobs.size());
    // Each worker writes through one tracked temporary file.
    const std::vector<std::exception_ptr> errors = run_batch(
        jobs.size(), std::min(o.jobs, kMaxTrackedTemporaries), [&] { return total_frames(jobs); },
        jobs.size() == 1 ? "render" : fmt::format("render {} files", jobs.size()),
        [&](size_t i, const AddFrames& add_frames) {
            int64_t reported = 0;
            summaries[i] =
                render_one(jobs[i], settings, actuator, o.channels, [&](int64_t done, int64_t) {
                    add_frames(done - reported);
                    reported = done;
                });
        });
    size_t failed = 0;
    for (size_t i = 0; i < jobs.size(); ++i) {
        if (!errors[i]) {
            std::cerr << summaries[i] << '\n';
            continue;
        }
        if (jobs.size() == 1) std::rethrow_exception(errors[i]);
        ++failed;
        try {
            std::rethrow_exception(errors[i]);
        } catch (const std::exception& e) {
            std::cerr << "tactus: error: " << e.what() << '\n';
        }
    }
    if (failed > 0)
        throw std::runtime_error(fmt::format(
            "render: {} of {} files failed, the others were written", failed, jobs.size()));
}

}  // namespace

void add_render(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = app.add_subcommand("render", "render the vibration for audio files");
    command
        ->add_option("inputs", options->inputs,
                     "audio files (anything libsndfile reads); several need -O")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", options->output,
                        "vibration file to write (.wav), one input");
    command->add_option("-O,--output-dir", options->output_dir,
                        "directory for the vibration files: DIR/<input name without its "
                        "extension>.vibration.wav (created if missing)");
    command->add_option("-j,--jobs", options->jobs, "files rendered at once, one per thread")
        ->check(CLI::Range(1, 1024))
        ->capture_default_str();
    command->add_option("--channels,-c", options->channels, "identical actuator channels")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    add_actuator_option(*command, options->actuator,
                        "actuator profile (name in actuators/ or FILE.toml): compensate its "
                        "response, respect its max drive, warn about what it cannot do");
    add_force_option(*command, options->force);
    options->pipeline.add_to(*command);
    command->callback([options] { render(*options); });
}

}  // namespace tactus::cli
