// The studio's requests, apart from the HTTP server that carries them (server.cpp), so that a
// fuzz target and the tests drive the same code: every request checked against the session's
// token, every file named by its listed name, every error one line (as the command line states
// it) in {"error": ...}. Any thread; renders and exports run one at a time.
#pragma once

#include <map>
#include <string>

#include "session.hpp"

namespace tactus::cli {

struct StudioRequest {
    std::string method{};  // "GET", "POST"
    std::string path{};    // "/api/render", without the query
    std::map<std::string, std::string> query{};
    std::string token{};  // the `token` query parameter or the X-Tactus-Token header
    std::string body{};
};

struct StudioResponse {
    int status = 200;
    // With its charset: cpp-httplib compresses a bare "application/json" (and text/*) for a
    // browser with Brotli, which took 2 s for a render's 1.4 MB; on loopback it only costs.
    std::string content_type = "application/json; charset=utf-8";
    std::string body{};
    std::string download_name{};  // set: the body is a file to save under this name
};

// GET  /                      the page
// GET  /api/params            {params: the table (params_json.hpp), presets, actuators}
// GET  /api/preset?name=N     {key: value text} of preset N
// GET  /api/files             {files: [name...]}
// POST /api/upload?name=N     body: the file's bytes -> {file: N}
// POST /api/render            {file, preset, settings: {key: text}, actuator, have: {plot id:
//                             digest}} -> the plots (each with its digest; one whose digest
//                             the page sent is only named: {id, digest, same: true}), onsets
//                             and figures, and `render`: the id of its samples
// GET  /api/samples?render=ID&what=vibration|sound   float32 little-endian
// POST /api/preset            {preset, settings} -> the preset's text (a .toml download)
// POST /api/export            {file, preset, settings, actuator, format} -> the file
StudioResponse handle_request(StudioSession& session, const StudioRequest& request);

}  // namespace tactus::cli
