// tactus simulate FILE -o OUT [--actuator NAME]: what an actuator does with a vibration file: its
// drive through the profile's time-domain model (actuator/actuator_model.hpp), written as the
// displacement, full scale = the profile's displacement_um (peak), each channel its own motor.
#include <fmt/format.h>

#include "actuator_option.hpp"
#include "batch_plan.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "global_options.hpp"
#include "tactus/actuator/actuator_model.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/audio_writer.hpp"
#include "tactus/io/render_info.hpp"

namespace tactus::cli {
namespace {

struct SimulateOptions {
    std::string input, output, actuator;  // empty: the one the file was rendered for
    bool force = false;
    BatchOptions batch;
};

void simulate(const SimulateOptions& o) {
    check_output(o.input, o.output, o.force);
    writable_sound_format(o.output, SampleFormat::float32);
    const ActuatorProfile actuator = actuator_of_vibration(o.actuator, o.input, "simulated");
    const RenderInfo how{.source = std::filesystem::path(o.input).filename().string(),
                         .preset = {},
                         .changes = {},
                         .actuator = {},  // a displacement: metering it again would not apply
                         .version = TACTUS_VERSION};
    std::vector<ActuatorModel> models;
    std::vector<std::vector<float>> out;
    std::vector<float*> pointers;
    std::optional<AudioWriter> writer;
    float peak = 0.0f;
    Progress progress("simulate");
    const RunSummary run = stream_file(
        o.input,
        [&](const ProcessSpec& spec) {
            models.resize(static_cast<size_t>(spec.channels));
            for (auto& model : models) model.prepare(spec, actuator);
            out.assign(models.size(), std::vector<float>(kStreamBlockFrames));
            pointers.clear();
            for (auto& channel : out) pointers.push_back(channel.data());
            writer.emplace(o.output, spec.sample_rate_hz, spec.channels, SampleFormat::float32,
                           SoundTags{.software = "tactus " + how.version,
                                     .comment = fmt::format("displacement through {}, full scale "
                                                            "{:g} um; {}",
                                                            actuator.name, actuator.displacement_um,
                                                            how.comment())});
        },
        [&](const float* const* in, int frames) {
            for (size_t c = 0; c < models.size(); ++c) {
                models[c].process(in[c], pointers[c], frames);
                for (int i = 0; i < frames; ++i) peak = std::max(peak, std::abs(pointers[c][i]));
            }
            writer->write(pointers.data(), frames);
        },
        with_progress(progress));
    writer->commit();
    note(fmt::format("{}: {:.2f} s through {} ({}), peak {:.3g} um", o.output,
                     run.frames / run.sample_rate_hz, actuator.name, type_name(actuator.type),
                     peak * actuator.displacement_um));
}

}  // namespace

void add_simulate(CLI::App& app) {
    auto options = std::make_shared<SimulateOptions>();
    CLI::App* command = app.add_subcommand(
        "simulate",
        "what an actuator does with a vibration file: its displacement through the profile's "
        "model (an LRA's resonance, an ERM's spin-up and speed-tied frequency)");
    options->batch.output_needed = true;
    options->batch.add_to(*command,
                          "displacement file to write (float), one input: full scale = the "
                          "profile's displacement_um",
                          ".displacement.wav");
    add_actuator_option(
        *command, options->actuator,
        "actuator profile (name in actuators/ or FILE.toml; default: the one the file was "
        "rendered for, as its comment says, else voice-coil)");
    command->callback([options] { for_each_input(*options, ".displacement.wav", simulate); });
}

}  // namespace tactus::cli
