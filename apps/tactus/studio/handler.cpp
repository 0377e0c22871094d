#include "handler.hpp"

#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "export.hpp"
#include "page.hpp"
#include "params_json.hpp"
#include "pipeline_options.hpp"
#include "plot_digest.hpp"
#include "report_render.hpp"
#include "tactus/export/haptic_formats.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/io/search_path.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus::cli {
namespace {

using nlohmann::json;

// A request refused with its HTTP status and one line saying why.
struct Refused : std::runtime_error {
    Refused(int status_code, const std::string& what)
        : std::runtime_error(what), status(status_code) {}
    int status;
};

// Names and messages may hold any bytes (a file's name): invalid UTF-8 is replaced, not thrown.
std::string text_of_json(const json& body) {
    return body.dump(-1, ' ', false, json::error_handler_t::replace);
}

StudioResponse json_response(const json& body) {
    return {.body = text_of_json(body)};
}

std::vector<std::string> preset_names() {
    std::vector<std::string> names;
    for (const PresetInfo& p : list_presets()) names.push_back(p.name);
    return names;
}

std::vector<std::string> actuator_names() {
    std::vector<std::string> names;
    for (const auto& [name, path] : toml_files(actuator_search_path())) names.push_back(name);
    return names;
}

std::string text_of(const json& value) {
    return value.is_string() ? value.get<std::string>() : text_of_json(value);
}

// A string field of the body; `fallback` when it is missing.
std::string field(const json& body, const char* name, const std::string& fallback = {}) {
    if (!body.contains(name)) return fallback;
    if (!body[name].is_string()) throw Refused(400, fmt::format("'{}' must be a string", name));
    return body[name].get<std::string>();
}

// The preset (one of the listed names, never a path) and the settings as the command line's
// --set, in the table's order: the same options `tactus render --set` would be given.
PipelineOptions pipeline_of(const json& body) {
    PipelineOptions pipeline;
    pipeline.preset = field(body, "preset", kDefaultPreset);
    const auto names = preset_names();
    if (std::find(names.begin(), names.end(), pipeline.preset) == names.end())
        throw Refused(404, fmt::format("{}: no such preset", pipeline.preset));
    if (!body.contains("settings")) return pipeline;
    const json& settings = body["settings"];
    if (!settings.is_object()) throw Refused(400, "'settings' must be an object of key: value");
    for (const ParamSpec& s : param_table())
        if (const auto it = settings.find(std::string(s.key)); it != settings.end())
            pipeline.assignments.push_back(fmt::format("{}={}", s.key, text_of(*it)));
    for (const auto& [key, value] : settings.items())
        if (!find_param(key)) pipeline.assignments.push_back(key + "=" + text_of(value));
    return pipeline;
}

std::optional<ActuatorProfile> actuator_of(const std::string& name) {
    if (name.empty()) return std::nullopt;
    const auto names = actuator_names();
    if (std::find(names.begin(), names.end(), name) == names.end())
        throw Refused(404, fmt::format("{}: no such actuator", name));
    return load_actuator(resolve_actuator(name));
}

std::filesystem::path listed_file(const StudioSession& session, const std::string& name) {
    const auto path = session.file(name);
    if (!path) throw Refused(404, fmt::format("{}: not a file of this session", name));
    return *path;
}

json parse_body(const StudioRequest& request) {
    json body = json::parse(request.body, nullptr, false);
    if (body.is_discarded() || !body.is_object())
        throw Refused(400, fmt::format("{}: the body is not a JSON object", request.path));
    return body;
}

// Whole renders and exports one at a time: the machine's cores are the engine's.
std::mutex& render_mutex() {
    static std::mutex mutex;
    return mutex;
}

StudioResponse render(StudioSession& session, const StudioRequest& request) {
    const json body = parse_body(request);
    const std::string name = field(body, "file");
    const std::filesystem::path input = listed_file(session, name);
    const PipelineOptions pipeline = pipeline_of(body);
    const Settings settings = pipeline.resolve();
    const auto actuator = actuator_of(field(body, "actuator"));
    std::lock_guard lock(render_mutex());
    const auto start = std::chrono::steady_clock::now();
    ReportRender r = render_report(input.string(), settings, actuator, {}, &session.analyses());
    const double render_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    json out{{"file", name},
             {"sample_rate_hz", r.sample_rate_hz},
             {"latency_frames", r.latency_frames},
             {"frames", r.vibration.size()},
             {"render_ms", render_ms},
             {"metered", r.metered.front().metered_name},
             {"analysis", r.analysis_replayed ? "replayed" : "analysed"},
             {"set", pipeline.assignments}};
    for (const ReportOnset& o : r.onsets)
        out["onsets"].push_back({o.time_s, std::string(name_of(o.part))});
    if (!out.contains("onsets")) out["onsets"] = json::array();
    // The plots the page holds already (the digests it sent back): named, not sent again.
    const json have = body.contains("have") && body["have"].is_object() ? body["have"] : json{};
    for (const ReportPlot& p : r.plots) {
        const std::string digest = plot_digest(p, r.onsets);
        if (const auto it = have.find(p.id); it != have.end() && *it == digest) {
            out["plots"].push_back({{"id", p.id}, {"digest", digest}, {"same", true}});
            continue;
        }
        out["plots"].push_back({{"id", p.id},
                                {"digest", digest},
                                {"title", p.title},
                                {"y_label", p.y_label},
                                {"labels", p.labels},
                                {"rows", p.rows},
                                {"log_y", p.log_y},
                                {"onsets", p.onsets},
                                {"band", p.band},
                                {"points", p.points},
                                {"right_axis", p.right_axis}});
    }
    const perception::MeterSummary& summary = r.metered.front().summary;  // its one output
    for (const auto& c : perception::kChannels)
        out["channels"].push_back(
            {{"name", c.name},
             {"max_db", summary.channels[static_cast<int>(c.channel)].max_db},
             {"engaged", summary.channels[static_cast<int>(c.channel)].engaged_fraction}});
    auto samples = std::make_shared<StudioSession::Samples>();
    samples->sound = std::move(r.sound);
    samples->vibration = std::move(r.vibration);
    out["render"] = session.keep_render(std::move(samples));
    return json_response(out);
}

StudioResponse samples(const StudioSession& session, const StudioRequest& request) {
    int64_t id = 0;
    try {
        id = std::stoll(request.query.count("render") ? request.query.at("render") : "");
    } catch (const std::exception&) {
        throw Refused(400, "render: not a render's number");
    }
    const auto kept = session.render(id);
    if (!kept) throw Refused(404, fmt::format("render {}: not kept (render again)", id));
    const std::string what = request.query.count("what") ? request.query.at("what") : "vibration";
    if (what != "vibration" && what != "sound")
        throw Refused(400, fmt::format("what: '{}' is neither vibration nor sound", what));
    const std::vector<float>& v = what == "sound" ? kept->sound : kept->vibration;
    return {.content_type = "application/octet-stream",
            .body = std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float))};
}

StudioResponse preset(const StudioRequest& request) {
    const json body = parse_body(request);
    const PipelineOptions pipeline = pipeline_of(body);
    const Settings settings = pipeline.resolve();
    std::string name = field(body, "name", "studio.toml");
    check_plain_name(name);
    return {.content_type = "application/toml",
            .body = preset_text(settings, pipeline.description()),
            .download_name = name};
}

StudioResponse preset_values(const StudioRequest& request) {
    PipelineOptions pipeline;
    pipeline.preset = request.query.count("name") ? request.query.at("name") : kDefaultPreset;
    json body{{"preset", pipeline.preset}};
    pipeline = pipeline_of(body);
    const Settings settings = pipeline.resolve();
    json values = json::object();
    for (const ParamSpec& s : param_table()) values[std::string(s.key)] = settings.text_of(s.param);
    return json_response(values);
}

// The file `tactus export IN -o <name><format> --preset P --set ...` writes, read back.
StudioResponse export_file(StudioSession& session, const StudioRequest& request) {
    const json body = parse_body(request);
    const std::string name = field(body, "file");
    const std::filesystem::path input = listed_file(session, name);
    const std::string format = field(body, "format");
    if (haptic_format_of(format) != format)
        throw Refused(400, fmt::format("format: unknown export format '{}' (.ahap, .haptic, "
                                       ".android.json, .envelope.json, .ogg)",
                                       format));
    ExportOptions o;
    o.input = input.string();
    o.pipeline = pipeline_of(body);
    o.pipeline.resolve();
    o.actuator = field(body, "actuator");
    actuator_of(o.actuator);  // a listed name only
    const std::string download = input.stem().string() + format;
    const std::filesystem::path output = session.output_path(download);
    std::filesystem::create_directories(output.parent_path());
    o.outputs = {output.string()};
    o.force = true;
    std::string bytes;
    {
        std::lock_guard lock(render_mutex());
        export_files(o);
        std::ifstream in(output, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
        std::filesystem::remove(output);
    }
    return {.content_type = "application/octet-stream", .body = bytes, .download_name = download};
}

StudioResponse route(StudioSession& session, const StudioRequest& request) {
    const bool get = request.method == "GET", post = request.method == "POST";
    if (get && request.path == "/")
        return {.content_type = "text/html; charset=utf-8", .body = std::string(studio_page())};
    if (get && request.path == "/api/params")
        return json_response({{"params", params_json()},
                              {"presets", preset_names()},
                              {"actuators", actuator_names()},
                              {"default_preset", kDefaultPreset},
                              {"limits",
                               {{"upload_bytes", StudioSession::kMaxUploadBytes},
                                {"uploads", StudioSession::kMaxUploads}}}});
    if (get && request.path == "/api/preset") return preset_values(request);
    if (get && request.path == "/api/files")
        return json_response({{"files", session.file_names()}});
    if (get && request.path == "/api/samples") return samples(session, request);
    if (post && request.path == "/api/upload") {
        const std::string name = request.query.count("name") ? request.query.at("name") : "";
        return json_response({{"file", session.add_upload(name, request.body)}});
    }
    if (post && request.path == "/api/render") return render(session, request);
    if (post && request.path == "/api/preset") return preset(request);
    if (post && request.path == "/api/export") return export_file(session, request);
    throw Refused(404, fmt::format("{} {}: no such page", request.method, request.path));
}

StudioResponse error(int status, const std::string& what) {
    return {.status = status, .body = text_of_json(json{{"error", what}})};
}

}  // namespace

StudioResponse handle_request(StudioSession& session, const StudioRequest& request) {
    if (!session.token_matches(request.token))
        return error(403, "the session's token is missing or wrong (use the URL tactus printed)");
    try {
        return route(session, request);
    } catch (const Refused& e) {
        return error(e.status, e.what());
    } catch (const std::exception& e) {  // the command line's own one-line messages
        return error(400, e.what());
    }
}

}  // namespace tactus::cli
