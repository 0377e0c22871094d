#include "tactus/io/audio_reader.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

#include "tactus/dsp/downmix.hpp"
#include "tactus/io/mpeg_length_tag.hpp"

namespace tactus {
namespace {

// libsndfile opens a WAV, AIFF or W64 whose audio chunk is cut short and reads what is there;
// its log then holds e.g. "data : 1209600 (should be 19956)". Returns what is missing, or ""
// (also for the 0 and 0xFFFFFFFF lengths that streaming writers leave in an unfinished header).
std::string truncation(SNDFILE* file) {
    char log[8192] = {};
    sf_command(file, SFC_GET_LOG_INFO, log, sizeof log);
    std::string_view text = log;
    for (size_t start = 0; start < text.size();) {
        const size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        unsigned long long declared = 0, present = 0;
        if (!(line.starts_with("data :") || line.starts_with("SSND :"))) continue;
        if (std::sscanf(std::string(line).c_str(), "%*4s : %llu (should be %llu)", &declared,
                        &present) != 2)
            continue;
        if (declared == 0 || declared >= 0xFFFFFF00ull || present >= declared) continue;
        return fmt::format("the header announces {} bytes of audio, the file holds {}", declared,
                           present);
    }
    return {};
}

// Standard input as a seekable file: copied once (libsndfile reads few formats from a pipe,
// and a pipe can be read only once) into a temporary file that is unlinked at once, so it
// leaves nothing behind. Every reader of "-" gets its own descriptor on it.
int stdin_descriptor() {
    static const int spooled = [] {
        if (::lseek(STDIN_FILENO, 0, SEEK_CUR) >= 0) return STDIN_FILENO;  // a file: as it is
        std::string name =
            (std::filesystem::temp_directory_path() / "tactus-stdin-XXXXXX").string();
        const int fd = ::mkstemp(name.data());
        if (fd < 0) return -1;
        ::unlink(name.c_str());
        char buffer[1 << 16];
        for (ssize_t n; (n = ::read(STDIN_FILENO, buffer, sizeof buffer)) != 0;) {
            if (n < 0 && errno == EINTR) continue;
            if (n < 0 || ::write(fd, buffer, static_cast<size_t>(n)) != n) {
                ::close(fd);
                return -1;
            }
        }
        return fd;
    }();
    if (spooled < 0) return -1;
    const int fd = ::dup(spooled);
    if (fd >= 0) ::lseek(fd, 0, SEEK_SET);
    return fd;
}

// Whether the length libsndfile reports is the file's own statement (a header's or a tag's),
// which a stream ending early breaks, rather than an estimate from the file's size (an MPEG
// stream without a Xing, Info or VBRI tag: mpeg_length_tag.hpp).
bool length_is_stated(const std::filesystem::path& path, int format) {
    if ((format & SF_FORMAT_TYPEMASK) != SF_FORMAT_MPEG) return true;
    const int fd = path == "-" ? stdin_descriptor() : ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool stated = mpeg_file_states_length(fd);
    ::close(fd);
    return stated;
}

}  // namespace

AudioReader::AudioReader(const std::filesystem::path& path) : path_(path) {
    std::error_code error;
    if (std::filesystem::is_regular_file(path, error) &&
        std::filesystem::file_size(path, error) == 0)
        throw std::runtime_error(fmt::format("{}: empty file", path.string()));
    if (path == "-") {
        const int fd = stdin_descriptor();
        if (fd < 0)
            throw std::runtime_error(
                fmt::format("standard input: cannot read: {}", std::strerror(errno)));
        file_ = sf_open_fd(fd, SFM_READ, &info_, SF_TRUE);
    } else {
        file_ = sf_open(path.c_str(), SFM_READ, &info_);
    }
    if (!file_)
        throw std::runtime_error(
            fmt::format("{}: cannot read audio: {}", path.string(), sf_strerror(nullptr)));
    if (info_.channels < 1 || info_.samplerate < 1) {
        sf_close(file_);
        throw std::runtime_error(fmt::format("{}: no audio channels", path.string()));
    }
    if (const std::string cut = truncation(file_); !cut.empty()) {
        sf_close(file_);
        throw std::runtime_error(fmt::format("{}: truncated: {}", path.string(), cut));
    }
    length_stated_ = length_is_stated(path, info_.format);
    // Scale integer formats to [-1, 1) and do not clip floats.
    sf_command(file_, SFC_SET_NORM_FLOAT, nullptr, SF_TRUE);
}

AudioReader::~AudioReader() {
    if (file_) sf_close(file_);
}

int AudioReader::read(float* const* out, int max_frames) {
    const int channels = info_.channels;
    const auto samples = static_cast<size_t>(max_frames) * channels;
    // 16-bit PCM is read as integers and scaled here: libsndfile's own conversion to float
    // costs more than the whole WAV read.
    const bool pcm16 = (info_.format & SF_FORMAT_SUBMASK) == SF_FORMAT_PCM_16 &&
                       (info_.format & SF_FORMAT_TYPEMASK) != SF_FORMAT_FLAC;
    float* destination = out[0];
    if (channels > 1) {
        interleaved_.resize(samples);
        destination = interleaved_.data();
    }
    sf_count_t got = 0;
    if (pcm16) {
        pcm16_.resize(samples);
        got = sf_readf_short(file_, pcm16_.data(), max_frames);
        constexpr float kScale = 1.0f / 32768.0f;  // SFC_SET_NORM_FLOAT's scale for 16 bits
        for (sf_count_t i = 0; i < std::max<sf_count_t>(0, got) * channels; ++i)
            destination[i] = pcm16_[i] * kScale;
    } else {
        got = sf_readf_float(file_, destination, max_frames);
    }
    if (got < 0 || (got == 0 && sf_error(file_) != SF_ERR_NO_ERROR))
        throw std::runtime_error(fmt::format("{}: corrupt or truncated audio data: {}",
                                             path_.string(), sf_strerror(file_)));
    frames_read_ += got;
    // A stream that ends well before the length its file states (an MP3 cut short: its Xing
    // tag still holds the whole length) is truncated. One MPEG frame of slack (1152 samples,
    // twice) allows for an encoder's padding estimate. A length estimated from the file's size
    // promises nothing: the stream is read to its end, and only the decoder's errors count.
    constexpr int64_t kSlackFrames = int64_t{2} * 1152;
    const bool length_known =
        length_stated_ && info_.frames > 0 && info_.frames != SF_COUNT_MAX;  // not a pipe
    if (got == 0 && length_known && frames_read_ + kSlackFrames < info_.frames)
        throw std::runtime_error(fmt::format(
            "{}: truncated or corrupt: the header announces {} frames, only {} could be decoded",
            path_.string(), info_.frames, frames_read_));
    if (channels > 1)
        for (int c = 0; c < channels; ++c)
            for (sf_count_t i = 0; i < got; ++i) out[c][i] = interleaved_[i * channels + c];
    return static_cast<int>(got);
}

ChannelBlock::ChannelBlock(int channels, int frames)
    : samples_(static_cast<size_t>(channels) * frames), pointers_(static_cast<size_t>(channels)) {
    for (int c = 0; c < channels; ++c)
        pointers_[c] = samples_.data() + static_cast<size_t>(c) * frames;
}

MonoAudio read_mono(const std::filesystem::path& path) {
    AudioReader reader(path);
    MonoAudio audio{{}, reader.sample_rate_hz()};
    constexpr int kBlock = 4096;
    ChannelBlock block(reader.channels(), kBlock);
    std::vector<float> mono(kBlock);
    while (const int got = reader.read(block.data(), kBlock)) {
        downmix_mean(block.data(), reader.channels(), 0, mono.data(), got);
        audio.samples.insert(audio.samples.end(), mono.begin(), mono.begin() + got);
    }
    return audio;
}

}  // namespace tactus
