// tactus analyze IN [-o FILE.csv|FILE.json]: how it was made (version, preset, settings,
// actuator), then every analysis frame's features, the vibration parameters mapped from them, and
// the sensation level each channel of touch receives from the vibration through an actuator
// (perception/meter.hpp; readings are causal, every 10 ms). Streams: constant memory for any
// length.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <deque>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "actuator_option.hpp"
#include "batch_plan.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "global_options.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/render_info.hpp"
#include "tactus/io/text_output.hpp"
#include "tactus/perception/meter.hpp"

namespace tactus::cli {
namespace {

struct AnalyzeOptions {
    std::string input, output, format, actuator;
    bool force = false;
    BatchOptions batch;
    PipelineOptions pipeline;
};

constexpr const char* kColumns[] = {
    "time_s",    "loudness_db", "brightness_hz", "noisiness",    "pitch_hz",    "pitch_confidence",
    "onset_odf", "onset",       "onset_time_s",  "frequency_hz", "amplitude",   "square_mix",
    "trigger",   "attack_ms",   "decay_ms",      "sustain",      "flutter_hz",  "flutter_amplitude",
    "pressure",  "P_sl_db",     "NPI_sl_db",     "NPII_sl_db",   "NPIII_sl_db", "combined_sl_db"};
constexpr size_t kMeterColumns = 5;
using Row = std::array<double, std::size(kColumns)>;

// Holds each frame's row until the meter has seen the vibration up to the frame's time. The
// frames come off the engine's frame queue between process() calls, as a live front end takes
// them (nothing is stored from inside process()).
class FrameWriter {
  public:
    // How the frames were made heads the output: a comment line atop the CSV, the "tactus"
    // field of the JSON object (its rows in "frames").
    FrameWriter(std::ostream& out, bool json, const Engine& engine, ActuatorProfile actuator,
                const RenderInfo& how)
        : out_(out), json_(json), engine_(engine), actuator_(std::move(actuator)) {
        if (json_) {
            const nlohmann::ordered_json info = {{"version", how.version},
                                                 {"source", how.source},
                                                 {"preset", how.preset},
                                                 {"set", how.changes},
                                                 {"actuator", how.actuator}};
            out_ << "{\"tactus\": " << info.dump() << ",\n\"frames\": [\n";
        } else {
            out_ << "# " << how.comment() << '\n';
            for (size_t i = 0; i < std::size(kColumns); ++i) out_ << (i ? "," : "") << kColumns[i];
            out_ << '\n';
        }
    }
    void start(double sample_rate_hz) {
        meter_.prepare(
            sample_rate_hz, [this](double f) { return actuator_.displacement_um_at(f); },
            engine_.settings()[P::perception_contact_area_cm2]);
    }
    void vibration(const float* samples, int count) {
        meter_.write(samples, count,
                     [this](const perception::MeterReading& r) { readings_.push_back(r); });
        metered_samples_ += count;
        write_rows_up_to(static_cast<double>(metered_samples_));
    }
    void finish() {
        write_rows_up_to(INFINITY);
        if (json_) out_ << "\n]}\n";
    }

    // The engine's frames so far.
    void take_frames(Engine& engine) {
        for (AnalysisFrame frame; engine.pop_frame(frame);) add(frame.features, frame.control);
    }
    size_t rows() const { return rows_; }
    size_t onsets() const { return onsets_; }

  private:
    void add(const Features& f, const ControlFrame& c) {
        const double sample_rate_hz = engine_.sample_rate_hz();
        pending_.push_back({f.frame_end_sample / sample_rate_hz, f.loudness_db, f.brightness_hz,
                            f.noisiness, f.pitch_hz, f.pitch_confidence, f.onset_odf,
                            f.onset ? 1.0 : 0.0, f.onset ? f.onset_sample / sample_rate_hz : 0.0,
                            c.frequency_hz, c.amplitude, c.square_mix, c.trigger ? 1.0 : 0.0,
                            c.attack_ms, c.decay_ms, c.sustain, c.flutter_hz, c.flutter_amplitude,
                            c.pressure});
        onsets_ += f.onset;
    }
    // Writes the pending rows whose time (in samples) the meter has reached, each with the
    // latest reading at or before it.
    void write_rows_up_to(double samples) {
        const double sample_rate_hz = engine_.sample_rate_hz();
        while (!pending_.empty() && pending_.front()[0] * sample_rate_hz <= samples + 0.5) {
            Row values = pending_.front();
            pending_.pop_front();
            while (!readings_.empty() && readings_.front().time_s <= values[0] + 1e-9) {
                current_ = readings_.front();
                readings_.pop_front();
            }
            const size_t first = values.size() - kMeterColumns;
            for (size_t i = 0; i < current_.level_db.size(); ++i)
                values[first + i] = current_.level_db[i];
            values[first + current_.level_db.size()] = current_.combined_db;
            write_row(values);
        }
    }
    void write_row(const Row& values) {
        if (json_) {
            nlohmann::ordered_json row;
            for (size_t i = 0; i < std::size(kColumns); ++i) row[kColumns[i]] = values[i];
            out_ << (rows_ ? ",\n" : "") << row.dump();
        } else {
            for (size_t i = 0; i < std::size(values); ++i)
                out_ << (i ? "," : "") << fmt::format("{:.6g}", values[i]);
            out_ << '\n';
        }
        ++rows_;
    }

    std::ostream& out_;
    bool json_;
    const Engine& engine_;
    ActuatorProfile actuator_;
    perception::SensationMeter meter_;
    std::deque<Row> pending_;
    std::deque<perception::MeterReading> readings_;
    perception::MeterReading current_;
    int64_t metered_samples_ = 0;
    size_t rows_ = 0, onsets_ = 0;
};

void analyze(const AnalyzeOptions& o) {
    const Settings settings = o.pipeline.resolve();
    const std::filesystem::path out_path = o.output;
    std::string format = o.format;
    if (format.empty()) format = out_path.extension() == ".json" ? "json" : "csv";
    if (!is_stdout(o.output)) check_output(o.input, o.output, o.force);

    Engine engine(settings);
    // The vibration drives the named actuator (compensated, as render does) or, by default, is
    // metered through the default one as rendered.
    std::optional<ActuatorProfile> actuator;
    if (!o.actuator.empty()) actuator = load_actuator_for(o.actuator, settings);
    engine.set_actuator(actuator);
    const ActuatorProfile metered =
        actuator ? *actuator : load_actuator(resolve_actuator(kDefaultActuator));
    const RenderInfo how{.source = std::filesystem::path(o.input).filename().string(),
                         .preset = o.pipeline.preset,
                         .changes = o.pipeline.assignments,
                         .actuator = metered.name,
                         .version = TACTUS_VERSION};
    TextOutput output(out_path);
    FrameWriter writer(output.stream(), format == "json", engine, metered, how);
    // A block brings at most one frame per hop; the shortest hop (analysis.hop_ms at its least,
    // 0.5 ms, at the lowest rate) is 4 samples: the queue holds every frame of a block.
    constexpr int kShortestHopSamples = static_cast<int>(0.5e-3 * Engine::kMinSampleRateHz);
    static_assert(kStreamBlockFrames / kShortestHopSamples <= Engine::kQueueCapacity);
    engine.enable_frame_queue();
    run_with_progress(
        o.input, engine, "analyze",
        {.on_output =
             [&](const float* const* v, int n) {
                 writer.take_frames(engine);
                 writer.vibration(v[0], n);
             },
         .on_start = [&](double sample_rate_hz, int) { writer.start(sample_rate_hz); }});
    writer.finish();
    output.commit();
    if (!is_stdout(o.output))
        note(fmt::format("{}: {} frames every {:.2f} ms, {} onsets", o.output, writer.rows(),
                         1e3 * engine.hop_samples() / engine.sample_rate_hz(), writer.onsets()));
}

}  // namespace

void add_analyze(CLI::App& app) {
    auto options = std::make_shared<AnalyzeOptions>();
    CLI::App* command = app.add_subcommand(
        "analyze", "print features and vibration parameters for every analysis frame");
    options->batch.add_to(*command, "FILE.csv or FILE.json, one input (default: CSV on stdout)",
                          ".features.csv (.json with --format json)");
    command->add_option("--format", options->format, "csv or json (default: from -o's extension)")
        ->check(CLI::IsMember({"csv", "json"}));
    add_actuator_option(*command, options->actuator,
                        "actuator profile (name or FILE.toml): compensate for it as render does "
                        "and meter through it (default: meter through voice-coil)");
    options->pipeline.add_to(*command);
    command->callback([options] {
        size_t skipped = 0;
        const auto jobs =
            plan_batch(options->batch,
                       options->format == "json" ? ".features.json" : ".features.csv", skipped);
        run_jobs(options->batch, jobs, "analyze", [&](const BatchJob& job) {
            AnalyzeOptions one = *options;
            one.input = job.input.string(), one.output = job.output.string();
            one.force = options->batch.force;
            analyze(one);
        });
    });
}

}  // namespace tactus::cli
