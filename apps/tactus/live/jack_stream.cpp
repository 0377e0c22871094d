#include "live/jack_stream.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <thread>

namespace tactus::live {
namespace {

using Clock = std::chrono::steady_clock;

// The names of `device`'s ports that take (`output`: playback) or give audio, in libjack's order.
std::vector<std::string> device_ports(jack_client_t* client, const std::string& device,
                                      bool output) {
    const std::unique_ptr<const char*, decltype(&jack_free)> ports(
        jack_get_ports(client, nullptr, JACK_DEFAULT_AUDIO_TYPE,
                       output ? JackPortIsInput : JackPortIsOutput),
        &jack_free);
    std::vector<std::string> names;
    for (const char** p = ports.get(); p && *p; ++p)
        if (std::string_view(*p).starts_with(device + ":")) names.emplace_back(*p);
    return names;
}

}  // namespace

JackStream::JackStream(const std::string& client_name, const Ports& output, const Ports& input)
    : output_(output), input_(input) {
    jack_status_t status{};
    client_ = jack_client_open(client_name.c_str(), JackNoStartServer, &status);
    if (!client_)
        throw std::runtime_error(
            fmt::format("JACK: cannot open client '{}' (is the server running? status 0x{:x})",
                        client_name, static_cast<unsigned>(status)));
    sample_rate_hz_ = jack_get_sample_rate(client_);
    block_frames_ = static_cast<int>(jack_get_buffer_size(client_));
    const auto add = [&](const Ports& device, bool out, std::vector<jack_port_t*>& ports) {
        const std::vector<std::string> theirs = device_ports(client_, device.device, out);
        if (device.channels > 0 &&
            device.first_channel + device.channels > static_cast<int>(theirs.size()))
            throw std::runtime_error(fmt::format(
                "JACK device '{}' has {} {} ports; {} asked for", device.device, theirs.size(),
                out ? "playback" : "capture", device.first_channel + device.channels));
        for (int c = 0; c < device.channels; ++c) {
            jack_port_t* port = jack_port_register(
                client_, fmt::format("{} {}", out ? "outport" : "inport", c).c_str(),
                JACK_DEFAULT_AUDIO_TYPE, out ? JackPortIsOutput : JackPortIsInput, 0);
            if (!port) throw std::runtime_error("JACK: cannot register a port");
            ports.push_back(port);
        }
        if (device.channels > 0) {  // RtAudio's figure: the device's first port, optimistic
            jack_latency_range_t range{};
            jack_port_get_latency_range(
                jack_port_by_name(client_,
                                  theirs[static_cast<size_t>(device.first_channel)].c_str()),
                out ? JackPlaybackLatency : JackCaptureLatency, &range);
            latency_frames_ += range.min;
        }
    };
    try {
        add(output_, true, out_ports_);
        add(input_, false, in_ports_);
    } catch (...) {
        jack_client_close(client_);
        throw;
    }
    out_.resize(out_ports_.size() * kChunkFrames);
    in_.resize(in_ports_.size() * kChunkFrames);
    jack_set_process_callback(client_, &JackStream::on_process, this);
    jack_set_xrun_callback(client_, &JackStream::on_xrun, this);
    jack_on_info_shutdown(client_, &JackStream::on_shutdown, this);
}

JackStream::~JackStream() {
    if (shut_down()) {  // the server dies: let it go, notifications and all, before closing
        const Clock::time_point at{Clock::duration(shut_down_at_.load(std::memory_order_acquire))};
        std::this_thread::sleep_until(at + kServerGone);
    }
    stop();
    jack_client_close(client_);
}

void JackStream::start(Process process, void* user) {
    process_ = process;
    user_ = user;
    if (jack_activate(client_) != 0) throw std::runtime_error("JACK: cannot activate the client");
    active_ = true;
    connect(out_ports_, output_, true);
    connect(in_ports_, input_, false);
}

void JackStream::connect(const std::vector<jack_port_t*>& mine, const Ports& device, bool output) {
    const std::vector<std::string> theirs = device_ports(client_, device.device, output);
    for (size_t c = 0; c < mine.size(); ++c) {
        const std::string& other = theirs.at(static_cast<size_t>(device.first_channel) + c);
        const char* own = jack_port_name(mine[c]);
        const int error = output ? jack_connect(client_, own, other.c_str())
                                 : jack_connect(client_, other.c_str(), own);
        if (error != 0 && error != EEXIST)
            throw std::runtime_error(fmt::format("JACK: cannot connect {} to {}", own, other));
    }
}

void JackStream::stop() noexcept {
    if (!active_) return;
    active_ = false;
    if (!shut_down()) jack_deactivate(client_);  // returns once the cycle under way is over
}

int JackStream::on_process(jack_nframes_t frames, void* self) noexcept {
    auto& s = *static_cast<JackStream*>(self);
    const unsigned xruns = s.xruns_.load(std::memory_order_relaxed);
    bool xrun = xruns != s.xruns_seen_;
    s.xruns_seen_ = xruns;
    const auto total = static_cast<int>(frames);
    for (int done = 0; done < total;) {
        const int count = std::min(kChunkFrames, total - done);
        for (size_t c = 0; c < s.in_ports_.size(); ++c) {
            const auto* port =
                static_cast<const float*>(jack_port_get_buffer(s.in_ports_[c], frames));
            std::copy_n(port + done, count, s.in_.data() + c * static_cast<size_t>(count));
        }
        s.process_(s.in_ports_.empty() ? nullptr : s.in_.data(), s.out_.data(), count, xrun,
                   s.user_);
        xrun = false;
        for (size_t c = 0; c < s.out_ports_.size(); ++c) {
            auto* port = static_cast<float*>(jack_port_get_buffer(s.out_ports_[c], frames));
            std::copy_n(s.out_.data() + c * static_cast<size_t>(count), count, port + done);
        }
        done += count;
    }
    return 0;
}

void JackStream::on_shutdown(jack_status_t, const char*, void* self) noexcept {
    auto& s = *static_cast<JackStream*>(self);
    s.shut_down_at_.store(Clock::now().time_since_epoch().count(), std::memory_order_relaxed);
    s.shut_down_.store(true, std::memory_order_release);
}

int JackStream::on_xrun(void* self) noexcept {
    static_cast<JackStream*>(self)->xruns_.fetch_add(1, std::memory_order_relaxed);
    return 0;
}

}  // namespace tactus::live
