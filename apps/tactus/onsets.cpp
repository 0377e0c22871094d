// tactus onsets IN: one onset per line, "onset_s decided_s strength". The first column alone is
// an onset list as aubioonset prints it and as onset evaluation tools read it.
#include <fmt/format.h>

#include "commands.hpp"
#include "common.hpp"
#include "pipeline_options.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus::cli {
namespace {

struct OnsetsOptions {
    std::string input, output;
    bool force = false;
    PipelineOptions pipeline;
};

class OnsetWriter final : public FrameObserver {
  public:
    OnsetWriter(std::ostream& out, const Engine& engine) : out_(out), engine_(engine) {}
    void on_frame(const Features& f, const ControlFrame&) noexcept override {
        if (!f.onset) return;
        const double sample_rate_hz = engine_.sample_rate_hz();
        out_ << fmt::format("{:.6f} {:.6f} {:.4g}\n", f.onset_sample / sample_rate_hz,
                            f.frame_end_sample / sample_rate_hz, f.onset_odf);
    }

  private:
    std::ostream& out_;
    const Engine& engine_;
};

void onsets(const OnsetsOptions& o) {
    const Settings settings = o.pipeline.resolve();
    if (!o.output.empty() && o.output != "-") check_output(o.input, o.output, o.force);
    Engine engine(settings);
    TextOutput output(o.output);
    OnsetWriter writer(output.stream(), engine);
    engine.set_observer(&writer);
    run_with_progress(o.input, engine, "onsets");
    output.commit();
}

}  // namespace

void add_onsets(CLI::App& app) {
    auto options = std::make_shared<OnsetsOptions>();
    CLI::App* command =
        app.add_subcommand("onsets", "print one onset per line: onset_s decided_s strength");
    command->add_option("input", options->input, "audio file")
        ->required()
        ->check(CLI::ExistingFile);
    command->add_option("-o,--output", options->output, "file to write (default: stdout)");
    add_force_option(*command, options->force);
    options->pipeline.add_to(*command);
    command->callback([options] { onsets(*options); });
}

}  // namespace tactus::cli
