// The OSC server of `tactus live`: a UDP socket on localhost (or the address --osc-port names),
// read on a thread of its own. Every packet is decoded (osc_packet.hpp) and checked against the
// address space (osc_address_space.hpp); a bad one gets one line on stderr and changes nothing.
// A burst of parameter messages is coalesced (the last value of each parameter) before it goes
// to the engine, whose change queue holds Engine::kChangeCapacity changes. Once a burst is
// applied, each message to a parameter's address (a value, none: a question, or one refused) is
// answered with the value now in force, and each preset applied with its name, sent from the
// server's port back to the address the message came from (as OSC tools expect a reply).
#pragma once

#include <atomic>
#include <functional>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "live_control.hpp"

namespace tactus::live {

// "[HOST:]PORT" (HOST defaults to 127.0.0.1); throws std::invalid_argument naming the option.
struct OscEndpoint {
    std::string host;
    int port = 0;
};
OscEndpoint parse_endpoint(const std::string& text, const std::string& option,
                           const std::string& default_host);

using OscReport = std::function<void(const std::string&)>;
// To the sender of packets[packet].
using OscReply = std::function<void(size_t packet, const OscMessage& reply)>;

// Applies the commands of one burst of packets: parameter changes coalesced, everything else in
// order; errors (one line each) go to `report`, then the answers to `reply` (if given). The
// server's work, apart from the socket; the fuzz target and the tests call it directly.
void handle_osc_packets(std::span<const std::vector<std::byte>> packets, LiveControl& control,
                        const OscReport& report, const OscReply& reply = {});

class OscServer {
  public:
    // Binds now (throws std::runtime_error naming the address); serves from start(). `report`
    // takes the refusals (default: "tactus: " + line on stderr).
    OscServer(const OscEndpoint& endpoint, LiveControl& control, OscReport report = {});
    ~OscServer();
    OscServer(const OscServer&) = delete;
    OscServer& operator=(const OscServer&) = delete;
    void start();
    int port() const { return port_; }

  private:
    void serve();
    LiveControl& control_;
    OscReport report_;
    int socket_ = -1;
    int port_ = 0;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace tactus::live
