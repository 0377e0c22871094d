// A stream on a JACK server through libjack itself, for DeviceStream's JACK devices.
//
// RtAudio 5.2's JACK backend closes a stream whose server died at once, on a thread of its own.
// libjack's jack_client_close() cancels the client's notification thread asynchronously
// (jack2's JackPosixThread: PTHREAD_CANCEL_ASYNCHRONOUS); a dying server still sends
// notifications, and a thread cancelled while it handles one leaves libjack's synchro lock held
// for good: every later jack_client_open() of the process blocks, and the device never comes
// back. Here the client of a dead server is closed only once the server has had kServerGone to
// leave, with its notifications.
#pragma once

#include <jack/jack.h>

#include <atomic>
#include <chrono>
#include <string>
#include <vector>

namespace tactus::live {

class JackStream {
  public:
    // Ports of a JACK device (a client such as "system"), as RtAudio counts them.
    struct Ports {
        std::string device;
        int channels = 0;  // 0: none
        int first_channel = 0;
    };
    // Audio thread: in: `inputs` channels one after another, out: `outputs` channels, `frames`
    // samples each; xrun: the server reported an over- or underrun since the last call.
    using Process = void (*)(const float* in, float* out, int frames, bool xrun,
                             void* user) noexcept;
    static constexpr std::chrono::seconds kServerGone{1};

    // Control thread: a client named `client_name` with a port per channel ("outport N",
    // "inport N", as RtAudio named them), not yet active. Throws std::runtime_error.
    JackStream(const std::string& client_name, const Ports& output, const Ports& input);
    ~JackStream();
    JackStream(const JackStream&) = delete;
    JackStream& operator=(const JackStream&) = delete;

    // Control thread: activates the client, calling `process` from JACK's thread, and connects
    // the ports to the devices'. Throws std::runtime_error.
    void start(Process process, void* user);
    // Control thread: no call of `process` is under way or to come once it returns.
    void stop() noexcept;

    double sample_rate_hz() const { return sample_rate_hz_; }
    int block_frames() const { return block_frames_; }
    // The devices' playback plus capture latency, in frames (the least of JACK's range).
    long latency_frames() const { return latency_frames_; }
    // Any thread: the server shut the client down (it died or threw the client out).
    bool shut_down() const { return shut_down_.load(std::memory_order_acquire); }

  private:
    // Frames per call of `process`: a larger JACK period is handed over in parts.
    static constexpr int kChunkFrames = 1024;
    static int on_process(jack_nframes_t frames, void* self) noexcept;
    static void on_shutdown(jack_status_t, const char*, void* self) noexcept;
    static int on_xrun(void* self) noexcept;
    void connect(const std::vector<jack_port_t*>& mine, const Ports& device, bool output);

    jack_client_t* client_ = nullptr;
    Ports output_, input_;
    std::vector<jack_port_t*> out_ports_, in_ports_;
    std::vector<float> out_, in_;  // kChunkFrames per channel: the callback's buffers
    Process process_ = nullptr;
    void* user_ = nullptr;
    bool active_ = false;
    double sample_rate_hz_ = 0;
    int block_frames_ = 0;
    long latency_frames_ = 0;
    std::atomic<bool> shut_down_{false};
    std::atomic<std::chrono::steady_clock::rep> shut_down_at_{0};  // steady_clock ticks
    std::atomic<unsigned> xruns_{0};  // written by libjack's notification thread
    unsigned xruns_seen_ = 0;         // the audio thread's
};

}  // namespace tactus::live
