// The studio's HTTP server (cpp-httplib): every request handed to handle_request, uploads
// bounded in size before they are read. Stops on SIGINT, SIGTERM or SIGHUP.
#pragma once

#include <functional>
#include <string>

#include "session.hpp"

namespace tactus::cli {

// Binds `host`:`port` (0: any free port), calls on_listening(the port) once it listens, then
// serves `session` until a signal ends it; throws std::runtime_error when it cannot bind.
void serve_studio(StudioSession& session, const std::string& host, int port,
                  const std::function<void(int port)>& on_listening);

}  // namespace tactus::cli
