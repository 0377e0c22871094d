// tactus export IN -o OUT... : the vibration as the platforms' haptic formats, each named by
// its output's ending: .ahap (Apple Core Haptics), .haptic (Meta Haptics SDK), .android.json
// (Android VibrationEffect.createWaveform), .envelope.json (Android's envelope effects), .ogg
// (the sound with the vibration as its last channels and ANDROID_HAPTIC=<n>, for Android's
// haptic-coupled playback). With --layout every actuator output gets its own file of each
// format but the .ogg, named by the output (OUT.left.ahap), and the .ogg one haptic channel
// each. One render feeds every output (src/tactus/export), each track normalised as --normalise
// and --gain-db say; a sustained sound left unfelt is said as render says it.
#include "export.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <iostream>
#include <map>
#include <optional>

#include "actuator_option.hpp"
#include "batch_plan.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "global_options.hpp"
#include "layout_option.hpp"
#include "pipeline_options.hpp"
#include "tactus/actuator/felt_floor.hpp"
#include "tactus/export/haptic_formats.hpp"
#include "tactus/export/normalisation.hpp"
#include "tactus/export/vorbis_writer.hpp"
#include "tactus/io/text_output.hpp"
#include "unfelt_sound.hpp"

namespace tactus::cli {
namespace {

// Android plays at most two haptic channels (AudioFormat haptic channel masks A and B).
constexpr int kMaxAndroidHapticChannels = 2;

// An output's file of `format` for a layout's output `name`: OUT.ahap -> OUT.name.ahap.
std::string output_file(const std::string& path, const std::string& format,
                        const std::string& name) {
    return path.substr(0, path.size() - format.size()) + "." + name +
           path.substr(path.size() - format.size());
}

}  // namespace

void export_files(const ExportOptions& o) {
    const Settings settings = o.pipeline.resolve();
    std::optional<Layout> layout;
    if (!o.layout.empty()) layout = load_layout(resolve_layout(o.layout));
    // Each text file: (path, format, the actuator output it is drawn from).
    struct TextFile {
        std::string path, format;
        size_t output = 0;
    };
    std::vector<TextFile> files;
    std::vector<std::string> formats;
    std::optional<std::string> ogg_path;
    for (const auto& output : o.outputs) {
        const std::string format = haptic_format_of(output);
        if (format.empty())
            throw std::runtime_error(
                fmt::format("{}: unknown export format (name it .ahap, .haptic, .android.json, "
                            ".envelope.json or .ogg)",
                            output));
        if (std::find(o.outputs.begin(), o.outputs.end(), output) !=
            o.outputs.begin() + static_cast<std::ptrdiff_t>(formats.size()))
            throw std::runtime_error(fmt::format("{}: named twice", output));
        if (format == ".ogg" && ogg_path)
            throw std::runtime_error(fmt::format(
                "{}: an export writes one .ogg ({} is one already)", output, *ogg_path));
        formats.push_back(format);
        if (format == ".ogg") {
            check_output(o.input, output, o.force);
            ogg_path = output;
        } else if (!layout) {
            files.push_back({output, format, 0});
        } else {
            for (size_t k = 0; k < layout->outputs.size(); ++k)
                files.push_back({output_file(output, format, layout->outputs[k].name), format, k});
        }
    }
    for (const TextFile& file : files) check_output(o.input, file.path, o.force);
    const int channels = layout ? static_cast<int>(layout->outputs.size()) : o.channels;
    if (ogg_path && channels > kMaxAndroidHapticChannels)
        throw std::runtime_error(fmt::format("{}: Android plays at most {} haptic channels, not {}",
                                             *ogg_path, kMaxAndroidHapticChannels, channels));
    std::optional<ActuatorProfile> actuator;
    if (!o.actuator.empty()) actuator = load_actuator_for(o.actuator, settings);
    std::vector<ActuatorOutput> outputs =
        layout ? layout_outputs(*layout, settings)
               : std::vector<ActuatorOutput>(static_cast<size_t>(channels),
                                             ActuatorOutput{.profile = actuator});
    const Normalisation normalisation = Normalisation::parse(o.normalise, o.gain_db);
    // Android plays on the phone's actuator: the one rendered for, else a phone's LRA.
    double android_floor = 0;
    if (std::find(formats.begin(), formats.end(), ".android.json") != formats.end())
        android_floor =
            felt_floor(outputs.front().profile ? *outputs.front().profile
                                               : load_actuator(resolve_actuator(kAndroidActuator)),
                       settings[P::perception_contact_area_cm2]);

    Engine engine(settings);
    engine.set_actuators(outputs);
    RenderInfo info = o.pipeline.render_info(o.input, actuator ? actuator->name : std::string());
    info.layout = o.layout;
    std::optional<VorbisWriter> ogg;
    std::vector<const float*> ogg_channels;
    AlignedSink sink;
    if (ogg_path)
        sink = [&](const float* const* audio, int audio_channels, const float* const* vibration,
                   int actuators, int frames) {
            if (!ogg)
                ogg.emplace(*ogg_path, engine.sample_rate_hz(), audio_channels + actuators,
                            std::vector<std::pair<std::string, std::string>>{
                                {"ANDROID_HAPTIC", std::to_string(actuators)},
                                {"ENCODER", "tactus " TACTUS_VERSION},
                                {"COMMENT", info.comment()}});
            ogg_channels.assign(audio, audio + audio_channels);
            ogg_channels.insert(ogg_channels.end(), vibration, vibration + actuators);
            ogg->write(ogg_channels.data(), frames);
        };
    Progress progress("export");
    UnfeltSound unfelt(settings);
    RunCallbacks callbacks = with_progress(progress);
    callbacks.on_output = [&](const float* const* vibration, int frames) {
        unfelt.on_output(vibration, engine.actuators(), frames);
    };
    std::vector<HapticTrack> tracks = render_haptic_tracks(
        o.input, engine, sink, callbacks,
        [&](const AnalysisFrame& frame) { unfelt.on_loudness(frame.features.loudness_db); },
        RunAnalysis::ahead);
    for (HapticTrack& track : tracks) {
        track.info = info;
        normalise(track, normalisation);
    }
    if (ogg_path && !ogg)
        throw std::runtime_error(fmt::format("{}: the input gave no audio to write", *ogg_path));
    // Every output is written before any is committed: a failure leaves none of them.
    std::deque<TextOutput> texts;
    for (const TextFile& file : files) {
        const HapticTrack& track = tracks[file.output];
        texts.emplace_back(file.path).stream()
            << (file.format == ".ahap"            ? ahap_text(track)
                : file.format == ".haptic"        ? meta_haptic_text(track)
                : file.format == ".envelope.json" ? android_envelope_text(track)
                                                  : android_waveform_text(track, android_floor));
    }
    if (ogg) ogg->commit();
    for (TextOutput& text : texts) text.commit();
    if (const std::string warning = unfelt.warning(o.input, engine.sample_rate_hz());
        !warning.empty())
        note(warning);
    for (const TextFile& file : files)
        note(fmt::format("{}: {:.3f} s, {} onsets", file.path, tracks[file.output].duration_s(),
                         tracks[file.output].onsets.size()));
    if (ogg_path)
        note(fmt::format("{}: {:.3f} s, {} onsets, {:g} Hz, {} haptic channel(s)", *ogg_path,
                         tracks.front().duration_s(), tracks.front().onsets.size(),
                         engine.sample_rate_hz(), channels));
}

// One input to -o (each of its outputs), or every input (folders walked) to
// DIR/.../<name><format> for each of --formats: the one batch path, one render per input.
void export_batch(const ExportOptions& o) {
    BatchOptions batch = o.batch;
    batch.output = o.outputs.empty() ? std::string() : o.outputs.front();
    if (!batch.output_dir.empty())
        for (const auto& format : o.formats)
            if (haptic_format_of(format) != format)
                throw std::runtime_error(
                    fmt::format("--formats: unknown format '{}' (.ahap, .haptic, .android.json, "
                                ".envelope.json, .ogg)",
                                format));
    // Without -O one job, to every -o; with it each input's outputs in every format.
    std::map<std::filesystem::path, std::vector<std::string>> outputs_of;
    std::vector<BatchJob> jobs;
    for (const auto& format : batch.output_dir.empty() ? std::vector<std::string>{""} : o.formats) {
        size_t skipped = 0;
        for (const BatchJob& job : plan_batch(batch, format, skipped)) {
            auto& outputs = outputs_of[job.input];
            if (outputs.empty()) jobs.push_back(job);
            if (batch.output_dir.empty())
                outputs = o.outputs;
            else
                outputs.push_back(job.output.string());
        }
    }
    run_jobs(batch, jobs, [&](const BatchJob& job, const AddFrames&) {
        ExportOptions one = o;
        one.input = job.input.string();
        one.outputs = outputs_of.at(job.input);
        one.force = o.batch.force;
        export_files(one);
        return std::string();
    });
}

void add_export(CLI::App& app) {
    auto options = std::make_shared<ExportOptions>();
    CLI::App* command = app.add_subcommand(
        "export",
        "write the vibration as haptic files: .ahap, .haptic, .android.json, .envelope.json, .ogg");
    options->batch.output_needed = true;
    options->batch.add_to(*command, {}, "<format> for each of --formats");
    command->add_option(
        "-o,--output", options->outputs,
        "OUT.ahap (Core Haptics), OUT.haptic (Meta Haptics SDK), OUT.android.json "
        "(VibrationEffect.createWaveform, API 26), OUT.envelope.json (BasicEnvelopeBuilder, API "
        "36), OUT.ogg (sound + haptic channels, ANDROID_HAPTIC); repeat -o for several from one "
        "render");
    command->add_option("--formats", options->formats, "with -O: the formats to write")
        ->delimiter(',')
        ->capture_default_str();
    command->add_option("--normalise,--normalize", options->normalise, normalisation_help())
        ->check([](const std::string& text) {
            try {
                Normalisation::parse(text);
                return std::string();
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
        })
        ->capture_default_str();
    command
        ->add_option("--gain-db", options->gain_db,
                     "gain after --normalise, dB (louder moments clip at full scale)")
        ->check([](const std::string& text) {
            char* end = nullptr;
            const double db = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0')
                return fmt::format("'{}' is not a number of dB", text);
            try {
                Normalisation::parse("peak", db);
                return std::string();
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
        })
        ->capture_default_str();
    CLI::Option* channels =
        command->add_option("--channels,-c", options->channels, "haptic channels in the .ogg")
            ->check(CLI::Range(1, kMaxAndroidHapticChannels))
            ->capture_default_str();
    add_actuator_option(*command, options->actuator,
                        "actuator profile (name in actuators/ or FILE.toml) the vibration is "
                        "rendered for");
    add_layout_option(*command, options->layout)
        ->excludes(channels)
        ->excludes(command->get_option("--actuator"));
    options->pipeline.add_to(*command);
    command->callback([options] { export_batch(*options); });
}

}  // namespace tactus::cli
