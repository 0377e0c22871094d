// The live tests' own JACK and OSC client, run against a JACK server of the test (dummy driver):
//   live_test_client record NAME CHANNELS SECONDS OUT.wav
//       registers input ports NAME:in_1 ... in_CHANNELS and records them, from activation, until
//       SIGTERM / SIGINT or SECONDS of audio (the server's clock: a busy synchronous server runs
//       slower than the wall clock) into a float WAV.
//   live_test_client filter NAME ACTUATOR.toml
//       NAME:in -> NAME:out through the actuator profile's band-pass resonance (a biquad whose
//       magnitude is ActuatorProfile::response_db's resonance term: an actuator the calibration
//       must measure), until SIGTERM / SIGINT.
//   live_test_client play NAME FILE
//       registers output ports NAME:out_1 ... (one per channel of FILE) and, once one of them is
//       connected and half a second has passed, plays FILE once, then silence; until SIGTERM.
//   live_test_client osc-send PORT ADDRESS [f VALUE | s TEXT]...
//       one OSC message to 127.0.0.1:PORT, sent with liblo.
//   live_test_client osc-ask PORT SECONDS ADDRESS [f VALUE | s TEXT]...
//       one OSC message to 127.0.0.1:PORT sent from a port of its own (liblo), then prints, as
//       osc-listen does, the first message that comes back to that port within SECONDS.
//   live_test_client osc-listen PORT SECONDS
//       prints every OSC message received on 127.0.0.1:PORT for SECONDS (or until SIGTERM), one
//       line each: the address, then the arguments.
// record, filter, play and osc-listen print "ready" on stdout once they listen.
#include <jack/jack.h>
#include <lo/lo.h>
#include <sndfile.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "tactus/io/actuator_file.hpp"

namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) {
    g_stop = true;
}

struct Recorder {
    std::vector<jack_port_t*> ports;
    std::vector<std::vector<float>> samples;  // preallocated: the callback only copies
    std::atomic<size_t> frames{0};
};

int record_block(jack_nframes_t n, void* arg) {
    auto& r = *static_cast<Recorder*>(arg);
    const size_t at = r.frames.load(std::memory_order_relaxed);
    const size_t count = std::min<size_t>(n, r.samples[0].size() - at);
    for (size_t c = 0; c < r.ports.size(); ++c) {
        const auto* in = static_cast<const float*>(jack_port_get_buffer(r.ports[c], n));
        std::memcpy(r.samples[c].data() + at, in, count * sizeof(float));
    }
    r.frames.store(at + count, std::memory_order_relaxed);
    return 0;
}

struct Filter {
    jack_port_t *in = nullptr, *out = nullptr;
    double b0 = 0, b1 = 0, b2 = 0, a1 = 0, a2 = 0, z1 = 0, z2 = 0;
};

int filter_block(jack_nframes_t n, void* arg) {
    auto& f = *static_cast<Filter*>(arg);
    const auto* in = static_cast<const float*>(jack_port_get_buffer(f.in, n));
    auto* out = static_cast<float*>(jack_port_get_buffer(f.out, n));
    for (jack_nframes_t i = 0; i < n; ++i) {  // transposed direct form II
        const double x = in[i];
        const double y = f.b0 * x + f.z1;
        f.z1 = f.b1 * x - f.a1 * y + f.z2;
        f.z2 = f.b2 * x - f.a2 * y;
        out[i] = static_cast<float>(y);
    }
    return 0;
}

jack_client_t* open_client(const char* name) {
    jack_status_t status{};
    jack_client_t* client = jack_client_open(name, JackNoStartServer, &status);
    if (!client)
        std::fprintf(stderr, "live_test_client: cannot open client %s (status 0x%x)\n", name,
                     status);
    return client;
}

void wait_for_stop(double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!g_stop && std::chrono::steady_clock::now() < end)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

int record(const char* name, int channels, double seconds, const char* path) {
    jack_client_t* client = open_client(name);
    if (!client) return 1;
    const double rate = jack_get_sample_rate(client);
    Recorder r;
    r.samples.assign(static_cast<size_t>(channels),
                     std::vector<float>(static_cast<size_t>(seconds * rate) + 1));
    for (int c = 0; c < channels; ++c)
        r.ports.push_back(jack_port_register(client, ("in_" + std::to_string(c + 1)).c_str(),
                                             JACK_DEFAULT_AUDIO_TYPE, JackPortIsInput, 0));
    jack_set_process_callback(client, record_block, &r);
    if (jack_activate(client) != 0) return 1;
    std::printf("ready\n");
    std::fflush(stdout);
    while (!g_stop && r.frames.load() < r.samples[0].size())
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    jack_deactivate(client);
    jack_client_close(client);
    const size_t frames = r.frames.load();
    SF_INFO info{};
    info.samplerate = static_cast<int>(rate);
    info.channels = channels;
    info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
    SNDFILE* file = sf_open(path, SFM_WRITE, &info);
    if (!file) return 1;
    std::vector<float> interleaved(frames * static_cast<size_t>(channels));
    for (size_t i = 0; i < frames; ++i)
        for (int c = 0; c < channels; ++c)
            interleaved[i * static_cast<size_t>(channels) + static_cast<size_t>(c)] =
                r.samples[static_cast<size_t>(c)][i];
    sf_writef_float(file, interleaved.data(), static_cast<sf_count_t>(frames));
    sf_close(file);
    return 0;
}

int filter(const char* name, const char* actuator_path) {
    const tactus::ActuatorProfile profile = tactus::load_actuator(actuator_path);
    if (profile.resonance != tactus::ResonanceKind::band_pass) {
        std::fprintf(stderr, "live_test_client: %s has no band-pass resonance\n", actuator_path);
        return 1;
    }
    jack_client_t* client = open_client(name);
    if (!client) return 1;
    const double rate = jack_get_sample_rate(client);
    // The analogue band-pass s/(Q w0) / (s^2/w0^2 + s/(Q w0) + 1) (magnitude 1 at w0; the
    // profile's resonance term), bilinear with w0 prewarped (RBJ's constant-peak band-pass).
    const double w0 = 2 * M_PI * profile.resonance_hz / rate;
    const double alpha = std::sin(w0) / (2 * profile.q), a0 = 1 + alpha;
    Filter f;
    f.b0 = alpha / a0;
    f.b1 = 0;
    f.b2 = -alpha / a0;
    f.a1 = -2 * std::cos(w0) / a0;
    f.a2 = (1 - alpha) / a0;
    f.in = jack_port_register(client, "in", JACK_DEFAULT_AUDIO_TYPE, JackPortIsInput, 0);
    f.out = jack_port_register(client, "out", JACK_DEFAULT_AUDIO_TYPE, JackPortIsOutput, 0);
    jack_set_process_callback(client, filter_block, &f);
    if (jack_activate(client) != 0) return 1;
    std::printf("ready\n");
    std::fflush(stdout);
    wait_for_stop(1e9);
    jack_deactivate(client);
    jack_client_close(client);
    return 0;
}

struct Playback {
    std::vector<jack_port_t*> ports;
    std::vector<std::vector<float>> samples;
    std::atomic<bool> playing{false};
    size_t at = 0;
};

int play_block(jack_nframes_t n, void* arg) {
    auto& p = *static_cast<Playback*>(arg);
    const bool playing = p.playing.load(std::memory_order_acquire);
    for (size_t c = 0; c < p.ports.size(); ++c) {
        auto* out = static_cast<float*>(jack_port_get_buffer(p.ports[c], n));
        for (jack_nframes_t i = 0; i < n; ++i)
            out[i] = playing && p.at + i < p.samples[c].size() ? p.samples[c][p.at + i] : 0.0f;
    }
    if (playing) p.at += n;
    return 0;
}

int play(const char* name, const char* path) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path, SFM_READ, &info);
    if (!file) return 1;
    std::vector<float> interleaved(static_cast<size_t>(info.frames * info.channels));
    sf_readf_float(file, interleaved.data(), info.frames);
    sf_close(file);
    jack_client_t* client = open_client(name);
    if (!client) return 1;
    Playback p;
    p.samples.assign(static_cast<size_t>(info.channels),
                     std::vector<float>(static_cast<size_t>(info.frames)));
    for (size_t i = 0; i < static_cast<size_t>(info.frames); ++i)
        for (size_t c = 0; c < p.samples.size(); ++c)
            p.samples[c][i] = interleaved[i * p.samples.size() + c];
    for (int c = 0; c < info.channels; ++c)
        p.ports.push_back(jack_port_register(client, ("out_" + std::to_string(c + 1)).c_str(),
                                             JACK_DEFAULT_AUDIO_TYPE, JackPortIsOutput, 0));
    jack_set_process_callback(client, play_block, &p);
    if (jack_activate(client) != 0) return 1;
    std::printf("ready\n");
    std::fflush(stdout);
    while (!g_stop && jack_port_connected(p.ports[0]) == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    wait_for_stop(0.5);
    p.playing.store(true, std::memory_order_release);
    wait_for_stop(1e9);
    jack_deactivate(client);
    jack_client_close(client);
    return 0;
}

// argv: ADDRESS, then type and value pairs.
lo_message make_message(int argc, char** argv) {
    lo_message message = lo_message_new();
    for (int i = 1; i + 1 < argc; i += 2) {
        if (argv[i][0] == 'f')
            lo_message_add_float(message, std::stof(argv[i + 1]));
        else if (argv[i][0] == 'i')
            lo_message_add_int32(message, std::stoi(argv[i + 1]));
        else
            lo_message_add_string(message, argv[i + 1]);
    }
    return message;
}

int osc_send(const char* port, int argc, char** argv) {
    lo_address to = lo_address_new("127.0.0.1", port);
    lo_message message = make_message(argc, argv);
    const int sent = lo_send_message(to, argv[0], message);
    lo_message_free(message);
    lo_address_free(to);
    return sent > 0 ? 0 : 1;
}

int print_message(const char* path, const char* types, lo_arg** argv, int argc, lo_message, void*) {
    std::printf("%s", path);
    for (int i = 0; i < argc; ++i) {  // 4-byte aligned: read the bytes, not the lo_arg union
        const auto* bytes = reinterpret_cast<const char*>(argv[i]);
        float f = 0;
        int32_t n = 0;
        if (types[i] == LO_FLOAT) {
            std::memcpy(&f, bytes, sizeof f);
            std::printf(" %.9g", f);
        } else if (types[i] == LO_INT32) {
            std::memcpy(&n, bytes, sizeof n);
            std::printf(" %d", n);
        } else if (types[i] == LO_STRING) {
            std::printf(" %s", bytes);
        } else {
            std::printf(" ?%c", types[i]);
        }
    }
    std::printf("\n");
    return 0;
}

int osc_listen(const char* port, double seconds) {
    lo_server server = lo_server_new(port, nullptr);
    if (!server) return 1;
    lo_server_add_method(server, nullptr, nullptr, print_message, nullptr);
    std::printf("ready\n");
    std::fflush(stdout);
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!g_stop && std::chrono::steady_clock::now() < end) lo_server_recv_noblock(server, 10);
    std::fflush(stdout);
    lo_server_free(server);
    return 0;
}

int osc_ask(const char* port, double seconds, int argc, char** argv) {
    lo_server server = lo_server_new(nullptr, nullptr);
    if (!server) return 1;
    lo_server_add_method(server, nullptr, nullptr, print_message, nullptr);
    lo_address to = lo_address_new("127.0.0.1", port);
    lo_message message = make_message(argc, argv);
    const int sent = lo_send_message_from(to, server, argv[0], message);
    lo_message_free(message);
    lo_address_free(to);
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int received = 0;
    while (sent > 0 && received == 0 && std::chrono::steady_clock::now() < end)
        received = lo_server_recv_noblock(server, 10);
    std::fflush(stdout);
    lo_server_free(server);
    return sent > 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
    std::signal(SIGTERM, on_signal);
    std::signal(SIGINT, on_signal);
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "record" && argc == 6)
        return record(argv[2], std::stoi(argv[3]), std::stod(argv[4]), argv[5]);
    if (mode == "filter" && argc == 4) return filter(argv[2], argv[3]);
    if (mode == "play" && argc == 4) return play(argv[2], argv[3]);
    if (mode == "osc-send" && argc >= 4) return osc_send(argv[2], argc - 3, argv + 3);
    if (mode == "osc-listen" && argc == 4) return osc_listen(argv[2], std::stod(argv[3]));
    if (mode == "osc-ask" && argc >= 5)
        return osc_ask(argv[2], std::stod(argv[3]), argc - 4, argv + 4);
    std::fprintf(stderr,
                 "usage: live_test_client record NAME CHANNELS SECONDS OUT.wav\n"
                 "       live_test_client filter NAME ACTUATOR.toml\n"
                 "       live_test_client play NAME FILE\n"
                 "       live_test_client osc-send PORT ADDRESS [f VALUE | i VALUE | s TEXT]...\n"
                 "       live_test_client osc-ask PORT SECONDS ADDRESS [f VALUE | s TEXT]...\n"
                 "       live_test_client osc-listen PORT SECONDS\n");
    return 2;
}
