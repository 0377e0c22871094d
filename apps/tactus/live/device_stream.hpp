// An audio device stream: opens the named devices, calls an AudioCallback from the device's
// thread with non-interleaved float buffers, and says when the device went away so the caller
// can open it again. RtAudio finds the devices of every backend and runs ALSA and PulseAudio
// streams; JACK streams run through libjack itself (jack_stream.hpp says why).
#pragma once

#include <RtAudio.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "live/jack_stream.hpp"

namespace tactus::live {

// The audio thread's side of a stream. Both calls come from the device's thread only.
class AudioCallback {
  public:
    virtual ~AudioCallback() = default;
    // in: the input channels one after another (null without input), out: the output channels.
    virtual void process(const float* in, float* out, int frames) noexcept = 0;
    virtual void note_xrun() noexcept {}
};

// While one lives, alsa-lib prints nothing of its own (on a machine without a sound card it
// prints "ALSA lib confmisc.c:..." lines for every probe): RtAudio's errors say what matters,
// in the project's words. Control thread; the handler is the process's, restored on destruction.
class QuietAlsa {
  public:
    QuietAlsa();
    ~QuietAlsa();
    QuietAlsa(const QuietAlsa&) = delete;
    QuietAlsa& operator=(const QuietAlsa&) = delete;
};

// "jack", "alsa", "pulse": the backend names the command line takes (RtAudio's own).
RtAudio::Api backend_named(const std::string& name);
std::vector<RtAudio::Api> backends();

struct StreamRequest {
    RtAudio::Api backend = RtAudio::UNSPECIFIED;
    std::string input_device;  // name, part of a name, or index; empty: no input
    int input_channels = 0;    // opened from input_first_channel; -1: all the device has
    int input_first_channel = 0;
    std::string output_device;  // empty: the default output
    int output_channels = 0;
    double sample_rate_hz = 0;  // 0: the device's (JACK: the server's)
    // Only sample_rate_hz will do (--rate); else a rate the device does not run at (a file's,
    // say) gives way to the device's own.
    bool rate_required = false;
    int block_frames = 256;  // asked for: the device may run another (JACK: the server's)
    std::string client_name = "tactus";  // JACK's client name
};

class DeviceStream {
  public:
    // Opens (not starts) the stream; throws std::runtime_error naming the device and what RtAudio
    // said.
    DeviceStream(const StreamRequest& request);
    ~DeviceStream();
    DeviceStream(const DeviceStream&) = delete;
    DeviceStream& operator=(const DeviceStream&) = delete;

    // Calls `callback` from the device's thread until stop() or destruction.
    void start(AudioCallback& callback);
    void stop() noexcept;
    // Control thread: the stream stopped without stop() (the device or server went away), or
    // its callback has not been called for kSilentDevice (a device library that hangs as its
    // device goes away).
    bool lost();
    static constexpr std::chrono::seconds kSilentDevice{2};

    double sample_rate_hz() const { return sample_rate_hz_; }
    int block_frames() const { return static_cast<int>(block_frames_); }
    // "the JACK server runs" or "the device runs", for messages.
    std::string runs() const;
    // The device's input + output latency as RtAudio reports it, in frames.
    long device_latency_frames();
    std::string output_name() const { return output_name_; }
    int input_channels() const { return input_channels_; }

  private:
    static int on_audio(void* out, void* in, unsigned int frames, double, RtAudioStreamStatus,
                        void* self) noexcept;
    // The device's thread, from either library.
    static void deliver(const float* in, float* out, int frames, bool xrun, void* self) noexcept;
    std::unique_ptr<RtAudio> audio_;  // finds the devices; runs the stream but for JACK
    std::unique_ptr<JackStream> jack_;
    AudioCallback* callback_ = nullptr;
    int input_channels_ = 0;
    double sample_rate_hz_ = 0;
    unsigned int block_frames_ = 0;
    bool started_ = false;
    bool lost_ = false;
    std::atomic<uint64_t> callbacks_{0};  // written by the device's thread
    uint64_t callbacks_seen_ = 0;
    std::chrono::steady_clock::time_point callbacks_seen_at_;
    std::string output_name_;
};

// Every device of `audio` (control thread), each probed again for a moment if its server is
// busy; one that never answers stays unprobed, with no channels.
std::vector<RtAudio::DeviceInfo> probe_devices(RtAudio& audio);

struct Device {
    unsigned int id;
    RtAudio::DeviceInfo info;
};

// Device `name` among `devices` (probe_devices(audio), probed once for every lookup: each JACK
// probe is a client of its own), control thread: an exact name, an index, or the only device
// whose name contains it; the default one for "". Throws std::runtime_error listing what there
// is.
Device find_device(RtAudio& audio, const std::vector<RtAudio::DeviceInfo>& devices,
                   const std::string& name, bool output);

}  // namespace tactus::live
