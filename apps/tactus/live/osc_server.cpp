#include "osc_server.hpp"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <iostream>
#include <map>
#include <stdexcept>

#include "osc_packet.hpp"

namespace tactus::live {
namespace {

constexpr size_t kMaxPacketBytes = 65536;  // the largest UDP datagram
constexpr size_t kMaxBurstPackets = 1024;  // read before the changes are applied
constexpr int kPollMs = 50;                // how soon the thread notices it should stop

}  // namespace

OscEndpoint parse_endpoint(const std::string& text, const std::string& option,
                           const std::string& default_host) {
    OscEndpoint e{default_host, 0};
    std::string port = text;
    if (const size_t colon = text.rfind(':'); colon != std::string::npos) {
        e.host = text.substr(0, colon);
        port = text.substr(colon + 1);
    }
    const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), e.port);
    if (e.host.empty() || error != std::errc() || end != port.data() + port.size() || e.port < 1 ||
        e.port > 65535)
        throw std::invalid_argument(
            fmt::format("{} {}: give [HOST:]PORT with a port from 1 to 65535", option, text));
    return e;
}

void handle_osc_packets(std::span<const std::vector<std::byte>> packets, LiveControl& control,
                        const OscReport& report, const OscReply& reply) {
    std::map<P, double> pending;  // the burst's parameter changes, the last of each
    const auto flush = [&] {
        for (const auto& [id, value] : pending) try {
                control.set(id, value);
            } catch (const std::exception& e) {
                report(e.what());
            }
        pending.clear();
    };
    std::vector<std::pair<size_t, P>> asked;  // answered once the burst is applied
    std::vector<std::pair<size_t, std::string>> presets;
    for (size_t k = 0; k < packets.size(); ++k) {
        try {
            for (const OscMessage& message : decode_osc_packet(packets[k])) {
                if (const std::optional<P> id = parameter_of(message.address))
                    asked.emplace_back(k, *id);
                try {
                    const OscCommand command = parse_osc(message, control.actuators());
                    if (const auto* p = std::get_if<SetParameter>(&command)) {
                        pending[p->id] = p->value;
                        continue;
                    }
                    if (std::holds_alternative<QueryParameter>(command)) continue;
                    flush();  // in order with the parameters before it
                    control.run(command);
                    if (const auto* p = std::get_if<LoadPreset>(&command))
                        presets.emplace_back(k, p->name);
                } catch (const std::exception& e) {
                    report(e.what());
                }
            }
        } catch (const std::exception& e) {
            report(e.what());
        }
    }
    flush();
    if (!reply) return;
    const Settings now = control.settings();
    for (const auto& [k, name] : presets) reply(k, preset_reply(name));
    for (const auto& [k, id] : asked) reply(k, parameter_reply(id, now));
}

OscServer::OscServer(const OscEndpoint& endpoint, LiveControl& control, OscReport report)
    : control_(control), report_(std::move(report)) {
    if (!report_)
        report_ = [](const std::string& line) { std::cerr << "tactus: " << line << '\n'; };
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_DGRAM;
    hints.ai_flags = AI_PASSIVE;
    addrinfo* found = nullptr;
    const std::string port = std::to_string(endpoint.port);
    if (const int error = getaddrinfo(endpoint.host.c_str(), port.c_str(), &hints, &found))
        throw std::runtime_error(
            fmt::format("--osc-port {}:{}: {}", endpoint.host, endpoint.port, gai_strerror(error)));
    std::string why = "no address";
    for (addrinfo* a = found; a; a = a->ai_next) {
        socket_ = ::socket(a->ai_family, a->ai_socktype, a->ai_protocol);
        if (socket_ < 0) continue;
        if (::bind(socket_, a->ai_addr, a->ai_addrlen) == 0) break;
        why = std::strerror(errno);
        ::close(socket_);
        socket_ = -1;
    }
    freeaddrinfo(found);
    if (socket_ < 0)
        throw std::runtime_error(
            fmt::format("--osc-port {}:{}: cannot listen: {}", endpoint.host, endpoint.port, why));
    sockaddr_storage bound{};
    socklen_t length = sizeof bound;
    getsockname(socket_, reinterpret_cast<sockaddr*>(&bound), &length);
    port_ = ntohs(bound.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6*>(&bound)->sin6_port
                                              : reinterpret_cast<sockaddr_in*>(&bound)->sin_port);
}

OscServer::~OscServer() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    if (socket_ >= 0) ::close(socket_);
}

void OscServer::start() {
    thread_ = std::thread([this] { serve(); });
}

void OscServer::serve() {
    std::vector<std::vector<std::byte>> burst;
    std::vector<sockaddr_storage> senders;
    std::vector<socklen_t> sender_lengths;
    std::vector<std::byte> buffer(kMaxPacketBytes);
    const OscReply reply = [&](size_t packet, const OscMessage& message) {
        const std::vector<std::byte> bytes = encode_osc_message(message);
        // UDP: a sender that does not listen loses its answer; nothing to report.
        ::sendto(socket_, bytes.data(), bytes.size(), MSG_DONTWAIT,
                 reinterpret_cast<const sockaddr*>(&senders[packet]), sender_lengths[packet]);
    };
    while (!stop_) {
        pollfd waiting{.fd = socket_, .events = POLLIN, .revents = 0};
        if (::poll(&waiting, 1, kPollMs) <= 0) continue;
        burst.clear();
        senders.clear();
        sender_lengths.clear();
        while (burst.size() < kMaxBurstPackets) {
            sockaddr_storage from{};
            socklen_t length = sizeof from;
            const ssize_t n = ::recvfrom(socket_, buffer.data(), buffer.size(), MSG_DONTWAIT,
                                         reinterpret_cast<sockaddr*>(&from), &length);
            if (n < 0) break;
            burst.emplace_back(buffer.begin(), buffer.begin() + n);
            senders.push_back(from);
            sender_lengths.push_back(length);
        }
        handle_osc_packets(burst, control_, report_, reply);
    }
}

}  // namespace tactus::live
