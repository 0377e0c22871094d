#include "device_stream.hpp"

#include <alsa/asoundlib.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace tactus::live {
namespace {

extern "C" void ignore_alsa_error(const char*, int, const char*, int, const char*, ...) {}
std::atomic<int> g_quiet_alsa{0};  // QuietAlsa's alive: they nest

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

}  // namespace

QuietAlsa::QuietAlsa() {
    if (g_quiet_alsa++ == 0) snd_lib_error_set_handler(&ignore_alsa_error);
}

QuietAlsa::~QuietAlsa() {
    if (--g_quiet_alsa == 0) snd_lib_error_set_handler(nullptr);  // alsa-lib's default
}

std::vector<RtAudio::Api> backends() {
    std::vector<RtAudio::Api> apis;
    RtAudio::getCompiledApi(apis);
    std::erase(apis, RtAudio::RTAUDIO_DUMMY);
    return apis;
}

RtAudio::Api backend_named(const std::string& name) {
    const RtAudio::Api api = RtAudio::getCompiledApiByName(name);
    if (api == RtAudio::UNSPECIFIED || api == RtAudio::RTAUDIO_DUMMY) {
        std::string known;
        for (RtAudio::Api a : backends())
            known += (known.empty() ? "" : ", ") + RtAudio::getApiName(a);
        throw std::runtime_error(
            fmt::format("--backend {}: not a backend of this build (it has: {})", name, known));
    }
    return api;
}

std::vector<RtAudio::DeviceInfo> probe_devices(RtAudio& audio) {
    const QuietAlsa quiet;
    const unsigned int count = audio.getDeviceCount();
    std::vector<RtAudio::DeviceInfo> infos(count);
    // A JACK probe opens a client of its own, which a server busy with a graph change can refuse
    // for a moment: such a device reads as unprobed, with no channels. (An ALSA device that
    // cannot be opened stays so: it is not asked again.)
    const int attempts = audio.getCurrentApi() == RtAudio::UNIX_JACK ? 20 : 1;
    for (unsigned int i = 0; i < count; ++i) {
        for (int attempt = 0; attempt < attempts; ++attempt) {
            infos[i] = audio.getDeviceInfo(i);
            if (infos[i].probed || attempt + 1 == attempts) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(25));
        }
    }
    return infos;
}

Device find_device(RtAudio& audio, const std::vector<RtAudio::DeviceInfo>& infos,
                   const std::string& name, bool output) {
    const auto found = [&](unsigned int i) { return Device{i, infos[i]}; };
    if (name.empty()) {
        const unsigned int id =
            output ? audio.getDefaultOutputDevice() : audio.getDefaultInputDevice();
        if (id < infos.size()) return found(id);
    }
    const auto count = static_cast<unsigned int>(infos.size());
    const auto usable = [&](unsigned int i) {
        return output ? infos[i].outputChannels > 0 : infos[i].inputChannels > 0;
    };
    unsigned int index = 0;
    if (const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), index);
        error == std::errc() && end == name.data() + name.size() && index < count)
        return found(index);
    for (unsigned int i = 0; i < count; ++i)
        if (infos[i].name == name && usable(i)) return found(i);
    std::vector<unsigned int> partial;
    for (unsigned int i = 0; i < count; ++i)
        if (lower(infos[i].name).find(lower(name)) != std::string::npos && usable(i))
            partial.push_back(i);
    if (partial.size() == 1) return found(partial[0]);
    std::string known;
    for (unsigned int i = 0; i < count; ++i)
        if (usable(i))
            known += fmt::format("{}{}: {}", known.empty() ? "" : ", ", i, infos[i].name);
    throw std::runtime_error(
        fmt::format("{} device '{}': {} ({} devices: {})", output ? "output" : "input", name,
                    partial.empty() ? "no such device" : "more than one device matches",
                    RtAudio::getApiName(audio.getCurrentApi()), known.empty() ? "none" : known));
}

DeviceStream::DeviceStream(const StreamRequest& request) {
    const QuietAlsa quiet;
    try {
        audio_ = std::make_unique<RtAudio>(request.backend);
        audio_->showWarnings(false);
        const std::vector<RtAudio::DeviceInfo> devices = probe_devices(*audio_);
        if (devices.empty())
            throw std::runtime_error(fmt::format("{}: no devices (is the server running?)",
                                                 RtAudio::getApiName(audio_->getCurrentApi())));
        RtAudio::StreamParameters out_params, in_params;
        const auto [out_id, out_info] = find_device(*audio_, devices, request.output_device, true);
        out_params.deviceId = out_id;
        out_params.nChannels = static_cast<unsigned int>(request.output_channels);
        output_name_ = out_info.name;
        if (request.output_channels > static_cast<int>(out_info.outputChannels))
            throw std::runtime_error(fmt::format("output device '{}' has {} channels; {} asked for",
                                                 out_info.name, out_info.outputChannels,
                                                 request.output_channels));
        const bool with_input = request.input_channels != 0;
        std::string input_name;
        if (with_input) {
            const auto [in_id, in_info] =
                find_device(*audio_, devices, request.input_device, false);
            in_params.deviceId = in_id;
            input_name = in_info.name;
            input_channels_ = request.input_channels < 0 ? static_cast<int>(in_info.inputChannels)
                                                         : request.input_channels;
            in_params.nChannels = static_cast<unsigned int>(input_channels_);
            in_params.firstChannel = static_cast<unsigned int>(request.input_first_channel);
            if (request.input_first_channel + input_channels_ >
                static_cast<int>(in_info.inputChannels))
                throw std::runtime_error(fmt::format(
                    "input device '{}' has {} channels; channel {} asked for", in_info.name,
                    in_info.inputChannels, request.input_first_channel + input_channels_));
        }
        sample_rate_hz_ = request.sample_rate_hz;
        const std::vector<unsigned int>& rates = out_info.sampleRates;
        if (sample_rate_hz_ > 0 && !rates.empty() &&
            std::none_of(rates.begin(), rates.end(),
                         [&](unsigned int r) { return r == sample_rate_hz_; })) {
            if (request.rate_required)
                throw std::runtime_error(fmt::format(
                    "--rate {:g}: {} at {} Hz{}", sample_rate_hz_, runs(), fmt::join(rates, ", "),
                    audio_->getCurrentApi() == RtAudio::UNIX_JACK
                        ? " (a JACK client takes the server's rate: leave --rate out, or start "
                          "jackd with -r)"
                        : ""));
            sample_rate_hz_ = 0;  // the device's own
        }
        if (sample_rate_hz_ <= 0)
            sample_rate_hz_ =
                out_info.preferredSampleRate > 0
                    ? out_info.preferredSampleRate
                    : (out_info.sampleRates.empty() ? 48000 : out_info.sampleRates[0]);
        if (audio_->getCurrentApi() == RtAudio::UNIX_JACK) {  // through libjack: jack_stream.hpp
            jack_ = std::make_unique<JackStream>(
                request.client_name, JackStream::Ports{output_name_, request.output_channels, 0},
                JackStream::Ports{input_name, input_channels_, request.input_first_channel});
            sample_rate_hz_ = jack_->sample_rate_hz();
            block_frames_ = static_cast<unsigned int>(jack_->block_frames());
            return;
        }
        block_frames_ = static_cast<unsigned int>(request.block_frames);
        RtAudio::StreamOptions options;
        options.flags = RTAUDIO_NONINTERLEAVED | RTAUDIO_SCHEDULE_REALTIME;
        options.streamName = request.client_name;
        audio_->openStream(&out_params, with_input ? &in_params : nullptr, RTAUDIO_FLOAT32,
                           static_cast<unsigned int>(sample_rate_hz_), &block_frames_,
                           &DeviceStream::on_audio, this, &options);
        sample_rate_hz_ = audio_->getStreamSampleRate();
    } catch (const RtAudioError& e) {
        throw std::runtime_error(e.getMessage());
    }
}

std::string DeviceStream::runs() const {
    return audio_->getCurrentApi() == RtAudio::UNIX_JACK
               ? "the JACK server runs"
               : fmt::format("output device '{}' runs", output_name_);
}

DeviceStream::~DeviceStream() {
    stop();
    jack_.reset();
    try {
        if (audio_ && audio_->isStreamOpen()) audio_->closeStream();
    } catch (const RtAudioError&) {
    }
    // The stream is closed: the last callback's release is seen, and all it did comes before
    // the delete (the device library orders them too, but out of ThreadSanitizer's view).
    (void)callbacks_.load(std::memory_order_acquire);
}

void DeviceStream::start(AudioCallback& callback) {
    callback_ = &callback;
    try {
        if (jack_)
            jack_->start(&DeviceStream::deliver, this);
        else
            audio_->startStream();
        started_ = true;
        callbacks_seen_at_ = std::chrono::steady_clock::now();
    } catch (const RtAudioError& e) {
        throw std::runtime_error(e.getMessage());
    }
}

void DeviceStream::stop() noexcept {
    if (!started_) return;
    started_ = false;
    if (jack_) {
        jack_->stop();
        return;
    }
    // Aborted, not drained: every caller lets the tail play out before it stops, and a lost
    // device has nothing left to drain.
    try {
        if (audio_->isStreamRunning()) audio_->abortStream();
    } catch (const RtAudioError&) {
    }
}

bool DeviceStream::lost() {
    if (!started_) return false;
    const auto now = std::chrono::steady_clock::now();
    if (const uint64_t calls = callbacks_.load(std::memory_order_relaxed);
        calls != callbacks_seen_) {
        callbacks_seen_ = calls;
        callbacks_seen_at_ = now;
    }
    const bool stopped = jack_ ? jack_->shut_down() : !audio_->isStreamRunning();
    lost_ = lost_ || stopped || now - callbacks_seen_at_ >= kSilentDevice;
    return lost_;
}

long DeviceStream::device_latency_frames() {
    if (jack_) return jack_->latency_frames();
    try {
        return audio_->getStreamLatency();
    } catch (const RtAudioError&) {
        return 0;
    }
}

int DeviceStream::on_audio(void* out, void* in, unsigned int frames, double,
                           RtAudioStreamStatus status, void* self) noexcept {
    deliver(static_cast<const float*>(in), static_cast<float*>(out), static_cast<int>(frames),
            status != 0, self);
    return 0;
}

void DeviceStream::deliver(const float* in, float* out, int frames, bool xrun,
                           void* self) noexcept {
    auto& stream = *static_cast<DeviceStream*>(self);
    if (xrun) stream.callback_->note_xrun();
    stream.callback_->process(in, out, frames);
    // Last: released to the destructor's acquiring load, so that every callback is over,
    // whichever thread the device library ended it on, before the stream is deleted.
    stream.callbacks_.fetch_add(1, std::memory_order_release);
}

}  // namespace tactus::live
