// tactus analyze IN [-o FILE.csv|FILE.json]: every analysis frame's features, the vibration
// parameters mapped from them, and the sensation level each channel of touch receives from the
// vibration through an actuator (perception/meter.hpp; readings are causal, every 10 ms).
// Streams: constant memory for any length.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <deque>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "actuator_option.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/text_output.hpp"
#include "tactus/perception/meter.hpp"

namespace tactus::cli {
namespace {

struct AnalyzeOptions {
    std::string input, output, format, actuator;
    bool force = false;
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
    FrameWriter(std::ostream& out, bool json, const Engine& engine, ActuatorProfile actuator)
        : out_(out), json_(json), engine_(engine), actuator_(std::move(actuator)) {
        if (json_) {
            out_ << "[\n";
        } else {
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
        write_rows(false);
    }
    void finish() {
        write_rows(true);
        if (json_) out_ << "\n]\n";
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
    // Writes the pending rows the meter has read past, each with the sensation levels at its
    // own time: interpolated between the 10 ms readings around it, so they line up with
    // `meter -o` of the rendered vibration. `finished`: the rest, with the last reading.
    void write_rows(bool finished) {
        while (!pending_.empty()) {
            Row values = pending_.front();
            const double t = values[0];
            while (!readings_.empty() && readings_.front().time_s <= t + 1e-9) {
                before_ = readings_.front();
                readings_.pop_front();
            }
            if (readings_.empty() && !finished) return;  // the reading after t is yet to come
            pending_.pop_front();
            const perception::MeterReading& after = readings_.empty() ? before_ : readings_.front();
            const double span = after.time_s - before_.time_s;
            const double w = span > 0 ? (t - before_.time_s) / span : 0.0;
            const size_t first = values.size() - kMeterColumns;
            for (size_t i = 0; i < before_.level_db.size(); ++i)
                values[first + i] =
                    before_.level_db[i] + w * (after.level_db[i] - before_.level_db[i]);
            values[first + before_.level_db.size()] =
                before_.combined_db + w * (after.combined_db - before_.combined_db);
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
    perception::MeterReading before_;  // the latest reading at or before the next row
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
    TextOutput output(out_path);
    FrameWriter writer(output.stream(), format == "json", engine,
                       actuator ? *actuator : load_actuator(resolve_actuator(kDefaultActuator)));
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
        std::cerr << fmt::format(
            "{}: {} frames every {:.2f} ms, {} onsets\n", o.output, writer.rows(),
            1e3 * engine.hop_samples() / engine.sample_rate_hz(), writer.onsets());
}

}  // namespace

void add_analyze(CLI::App& app) {
    auto options = std::make_shared<AnalyzeOptions>();
    CLI::App* command = app.add_subcommand(
        "analyze", "print features and vibration parameters for every analysis frame");
    command->add_option("input", options->input, "audio file")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", options->output,
                        "FILE.csv or FILE.json (default: CSV on stdout)");
    command->add_option("--format", options->format, "csv or json (default: from -o's extension)")
        ->check(CLI::IsMember({"csv", "json"}));
    add_actuator_option(*command, options->actuator,
                        "actuator profile (name or FILE.toml): compensate for it as render does "
                        "and meter through it (default: meter through voice-coil)");
    add_force_option(*command, options->force);
    options->pipeline.add_to(*command);
    command->callback([options] { analyze(*options); });
}

}  // namespace tactus::cli
