#include "tactus/io/audio_writer.hpp"

#include <fmt/format.h>

#include <cctype>
#include <stdexcept>

#include "tactus/io/temporary_path.hpp"

namespace tactus {
namespace {

enum class Samples { pcm_or_float, pcm_only, compressed };
struct Container {
    const char* extension;
    int format;
    Samples samples;
};
constexpr Container kContainers[] = {
    {".wav", SF_FORMAT_WAV, Samples::pcm_or_float},
    {".flac", SF_FORMAT_FLAC, Samples::pcm_only},
    {".ogg", SF_FORMAT_OGG | SF_FORMAT_VORBIS, Samples::compressed},
    {".oga", SF_FORMAT_OGG | SF_FORMAT_VORBIS, Samples::compressed},
    {".mp3", SF_FORMAT_MPEG | SF_FORMAT_MPEG_LAYER_III, Samples::compressed},
    {".aiff", SF_FORMAT_AIFF, Samples::pcm_or_float},
    {".aif", SF_FORMAT_AIFF, Samples::pcm_or_float},
    {".w64", SF_FORMAT_W64, Samples::pcm_or_float},
    {".rf64", SF_FORMAT_RF64, Samples::pcm_or_float},
    {".caf", SF_FORMAT_CAF, Samples::pcm_or_float},
    {".au", SF_FORMAT_AU, Samples::pcm_or_float},
};

}  // namespace

std::string writable_sound_extensions() {
    std::string text;
    for (const Container& c : kContainers)
        text += (text.empty() ? "" : ", ") + std::string(c.extension);
    return text;
}

int writable_sound_format(const std::filesystem::path& path, SampleFormat sample) {
    // Stdout, a device or a pipe named without an extension ("-", /dev/stdout) gets WAV.
    std::string extension = path.extension().string();
    if (extension.empty() && written_in_place(path)) extension = ".wav";
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const Container* container = nullptr;
    for (const Container& c : kContainers)
        if (extension == c.extension) container = &c;
    if (!container)
        throw std::runtime_error(fmt::format("{}: cannot write sound as '{}' (name it {})",
                                             path.string(), extension,
                                             writable_sound_extensions()));
    switch (container->samples) {
        case Samples::compressed:
            if (sample != SampleFormat::automatic)
                throw std::runtime_error(
                    fmt::format("{}: {} is compressed and has no sample format to choose",
                                path.string(), extension));
            return container->format;
        case Samples::pcm_only:
            if (sample == SampleFormat::float32)
                throw std::runtime_error(fmt::format(
                    "{}: {} holds 16- or 24-bit samples, not float", path.string(), extension));
            return container->format |
                   (sample == SampleFormat::pcm16 ? SF_FORMAT_PCM_16 : SF_FORMAT_PCM_24);
        case Samples::pcm_or_float:
            break;
    }
    return container->format | (sample == SampleFormat::pcm16   ? SF_FORMAT_PCM_16
                                : sample == SampleFormat::pcm24 ? SF_FORMAT_PCM_24
                                                                : SF_FORMAT_FLOAT);
}

AudioWriter::AudioWriter(const std::filesystem::path& path, double sample_rate_hz, int channels,
                         SampleFormat sample, const SoundTags& tags)
    : path_(path), channels_(channels) {
    SF_INFO info{};
    info.samplerate = static_cast<int>(sample_rate_hz);
    info.channels = channels;
    info.format = writable_sound_format(path, sample);
    temporary_ = temporary_path_for(path);
    track_temporary(temporary_);
    file_ = sf_open(temporary_.c_str(), SFM_WRITE, &info);
    if (!file_) {
        const std::string reason = sf_strerror(nullptr);
        discard_temporary(temporary_);
        throw std::runtime_error(fmt::format("{}: cannot write: {}", path.string(), reason));
    }
    // Integer samples clip at full scale instead of wrapping round.
    sf_command(file_, SFC_SET_CLIPPING, nullptr, SF_TRUE);
    if (!tags.software.empty()) sf_set_string(file_, SF_STR_SOFTWARE, tags.software.c_str());
    if (!tags.comment.empty()) sf_set_string(file_, SF_STR_COMMENT, tags.comment.c_str());
}

AudioWriter::~AudioWriter() {
    if (file_) {
        sf_close(file_);
        discard_temporary(temporary_);
    }
}

void AudioWriter::write(const float* const* channels, int frames) {
    const float* data = channels[0];
    if (channels_ > 1) {
        interleaved_.resize(static_cast<size_t>(frames) * channels_);
        for (int c = 0; c < channels_; ++c)
            for (int i = 0; i < frames; ++i) interleaved_[i * channels_ + c] = channels[c][i];
        data = interleaved_.data();
    }
    if (sf_writef_float(file_, data, frames) != frames)
        throw std::runtime_error(
            fmt::format("{}: write failed: {}", path_.string(), sf_strerror(file_)));
}

void AudioWriter::commit() {
    sf_write_sync(file_);
    const int error = sf_close(file_);
    file_ = nullptr;
    if (error != 0) {
        discard_temporary(temporary_);
        throw std::runtime_error(
            fmt::format("{}: write failed: {}", path_.string(), sf_error_number(error)));
    }
    commit_temporary(temporary_, path_);
}

}  // namespace tactus
