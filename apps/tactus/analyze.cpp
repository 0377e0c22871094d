// tactus analyze IN [-o FILE.csv|FILE.json]: every analysis frame's features and the vibration
// parameters mapped from them. Streams: constant memory for any length.
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "common.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus::cli {
namespace {

struct AnalyzeOptions {
    std::string input, output, format;
    bool force = false;
    PipelineOptions pipeline;
};

constexpr const char* kColumns[] = {
    "time_s",    "loudness_db", "brightness_hz", "noisiness",    "pitch_hz",  "pitch_confidence",
    "onset_odf", "onset",       "onset_time_s",  "frequency_hz", "amplitude", "square_mix",
    "trigger",   "attack_ms",   "decay_ms",      "sustain"};

class FrameWriter final : public FrameObserver {
  public:
    FrameWriter(std::ostream& out, bool json, const Engine& engine)
        : out_(out), json_(json), engine_(engine) {
        if (json_) {
            out_ << "[\n";
        } else {
            for (size_t i = 0; i < std::size(kColumns); ++i) out_ << (i ? "," : "") << kColumns[i];
            out_ << '\n';
        }
    }
    void finish() {
        if (json_) out_ << "\n]\n";
    }

    void on_frame(const Features& f, const ControlFrame& c) noexcept override {
        const double sample_rate_hz = engine_.sample_rate_hz();
        const double values[] = {f.frame_end_sample / sample_rate_hz,
                                 f.loudness_db,
                                 f.brightness_hz,
                                 f.noisiness,
                                 f.pitch_hz,
                                 f.pitch_confidence,
                                 f.onset_odf,
                                 f.onset ? 1.0 : 0.0,
                                 f.onset ? f.onset_sample / sample_rate_hz : 0.0,
                                 c.frequency_hz,
                                 c.amplitude,
                                 c.square_mix,
                                 c.trigger ? 1.0 : 0.0,
                                 c.attack_ms,
                                 c.decay_ms,
                                 c.sustain};
        onsets_ += f.onset;
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
    size_t rows() const { return rows_; }
    size_t onsets() const { return onsets_; }

  private:
    std::ostream& out_;
    bool json_;
    const Engine& engine_;
    size_t rows_ = 0, onsets_ = 0;
};

void analyze(const AnalyzeOptions& o) {
    const Settings settings = o.pipeline.resolve();
    const std::filesystem::path out_path = o.output;
    std::string format = o.format;
    if (format.empty()) format = out_path.extension() == ".json" ? "json" : "csv";
    if (!o.output.empty() && o.output != "-") check_output(o.input, o.output, o.force);

    Engine engine(settings);
    TextOutput output(out_path);
    FrameWriter writer(output.stream(), format == "json", engine);
    engine.set_observer(&writer);
    run_with_progress(o.input, engine, "analyze");
    writer.finish();
    output.commit();
    if (!o.output.empty() && o.output != "-")
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
    add_force_option(*command, options->force);
    options->pipeline.add_to(*command);
    command->callback([options] { analyze(*options); });
}

}  // namespace tactus::cli
