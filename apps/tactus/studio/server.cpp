#include "server.hpp"

#include <fmt/format.h>
#include <httplib.h>
#include <pthread.h>
#include <signal.h>
#include <sys/socket.h>

#include <thread>

#include "handler.hpp"

namespace tactus::cli {
namespace {

StudioRequest request_of(const httplib::Request& req) {
    StudioRequest r{.method = req.method, .path = req.path, .body = req.body};
    for (const auto& [key, value] : req.params) r.query.emplace(key, value);
    r.token = req.has_header("X-Tactus-Token") ? req.get_header_value("X-Tactus-Token")
              : r.query.count("token")         ? r.query.at("token")
                                               : std::string();
    return r;
}

}  // namespace

void serve_studio(StudioSession& session, const std::string& host, int port,
                  const std::function<void(int port)>& on_listening) {
    // The signals wait for the thread below (every thread the server starts inherits the mask).
    sigset_t signals;
    sigemptyset(&signals);
    for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, s);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);

    httplib::Server server;
    // SO_REUSEADDR only: cpp-httplib's default SO_REUSEPORT would let a second server (another
    // session) bind the same port and take half of this one's connections.
    server.set_socket_options([](int socket) {
        const int yes = 1;
        setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    server.set_payload_max_length(StudioSession::kMaxUploadBytes + (1u << 20));
    const auto handler = [&session](const httplib::Request& req, httplib::Response& res) {
        const StudioResponse out = handle_request(session, request_of(req));
        res.status = out.status;
        res.set_header("Cache-Control", "no-store");
        res.set_header("X-Content-Type-Options", "nosniff");
        if (!out.download_name.empty())
            res.set_header("Content-Disposition",
                           fmt::format("attachment; filename=\"{}\"", out.download_name));
        res.set_content(out.body, out.content_type.c_str());
    };
    server.Get(".*", handler);
    server.Post(".*", handler);
    server.set_exception_handler(
        [](const httplib::Request&, httplib::Response& res, const std::exception_ptr&) {
            res.status = 500;
            res.set_content(R"({"error":"internal error"})", "application/json");
        });
    const int bound =
        port == 0 ? server.bind_to_any_port(host) : (server.bind_to_port(host, port) ? port : -1);
    if (bound <= 0)
        throw std::runtime_error(fmt::format(
            "{}:{}: cannot listen there (address in use or not this machine's)", host, port));
    std::thread waiter([&server, signals] {
        int signal = 0;
        sigwait(&signals, &signal);
        server.stop();
    });
    on_listening(bound);
    server.listen_after_bind();
    if (waiter.joinable()) {
        // NOLINTNEXTLINE(bugprone-bad-signal-to-kill-thread): it interrupts a wait, kills nothing
        pthread_kill(waiter.native_handle(), SIGTERM);  // wakes it if the server stopped alone
        waiter.join();
    }
}

}  // namespace tactus::cli
