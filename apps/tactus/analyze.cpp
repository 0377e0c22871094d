// tactus analyze IN [-o FILE.csv|FILE.json]: how it was made (version, preset, settings,
// actuator), then every analysis frame's features, the vibration parameters mapped from them, and
// the sensation level each channel of touch receives from the vibration through an actuator
// (perception/meter.hpp; readings are causal, every 10 ms). Streams: constant memory for any
// length.
#include <fmt/format.h>

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
#include "tactus/io/analysis_rows.hpp"
#include "tactus/io/render_info.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus::cli {
namespace {

struct AnalyzeOptions {
    std::string input, output, format, actuator;
    bool force = false;
    BatchOptions batch;
    PipelineOptions pipeline;
};

// Writes AnalysisRows as CSV or JSON, the part column as the part's name. How the frames were
// made follows the CSV's header as a comment line (after it, so numpy.genfromtxt(names=True)
// takes the header's names; pandas.read_csv(comment="#") skips it too), and is the JSON object's
// "tactus" field (its rows in "frames").
class RowWriter {
  public:
    RowWriter(std::ostream& out, bool json, const RenderInfo& how) : out_(out), json_(json) {
        if (json_) {
            const nlohmann::ordered_json info = {{"version", how.version},
                                                 {"source", how.source},
                                                 {"preset", how.preset},
                                                 {"set", how.changes},
                                                 {"actuator", how.actuator}};
            out_ << "{\"tactus\": " << info.dump() << ",\n\"frames\": [\n";
        } else {
            for (size_t i = 0; i < AnalysisRows::kColumns.size(); ++i)
                out_ << (i ? "," : "") << AnalysisRows::kColumns[i];
            out_ << "\n# " << how.comment() << '\n';
        }
    }
    void write(const AnalysisRows::Row& values) {
        const std::string_view part = name_of(AnalysisRows::part_of(values));
        if (json_) {
            nlohmann::ordered_json row;
            for (size_t i = 0; i < values.size(); ++i) {
                const std::string name(AnalysisRows::kColumns[i]);
                if (i == AnalysisRows::kPartColumn)
                    row[name] = part;
                else
                    row[name] = values[i];
            }
            out_ << (rows_ ? ",\n" : "") << row.dump();
        } else {
            for (size_t i = 0; i < values.size(); ++i) {
                if (i) out_ << ',';
                if (i == AnalysisRows::kPartColumn)
                    out_ << part;
                else
                    out_ << fmt::format("{:.6g}", values[i]);
            }
            out_ << '\n';
        }
        ++rows_;
    }
    void finish() {
        if (json_) out_ << "\n]}\n";
    }

  private:
    std::ostream& out_;
    bool json_;
    size_t rows_ = 0;
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
    const RenderInfo how = o.pipeline.render_info(o.input, metered.name);
    TextOutput output(out_path);
    RowWriter writer(output.stream(), format == "json", how);
    AnalysisRows rows(engine, metered, [&](const AnalysisRows::Row& row) { writer.write(row); });
    // A block brings at most one frame per hop; the shortest hop (analysis.hop_ms at its least,
    // 0.5 ms, at the lowest rate) is 4 samples: the queue holds every frame of a block.
    constexpr int kShortestHopSamples = static_cast<int>(0.5e-3 * Engine::kMinSampleRateHz);
    static_assert(kStreamBlockFrames / kShortestHopSamples <= Engine::kQueueCapacity);
    engine.enable_frame_queue();
    run_with_progress(
        o.input, engine, "analyze",
        {.on_output =
             [&](const float* const* v, int n) {
                 rows.take_frames(engine);
                 rows.vibration(v[0], n);
             },
         .on_start = [&](double sample_rate_hz, int) { rows.start(sample_rate_hz); }});
    rows.finish();
    writer.finish();
    output.commit();
    if (!is_stdout(o.output))
        note(fmt::format("{}: {} frames every {:.2f} ms, {} onsets", o.output, rows.rows(),
                         1e3 * engine.hop_samples() / engine.sample_rate_hz(), rows.onsets()));
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
        for_each_input(*options, options->format == "json" ? ".features.json" : ".features.csv",
                       analyze);
    });
}

}  // namespace tactus::cli
