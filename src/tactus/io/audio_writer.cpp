#include "tactus/io/audio_writer.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "tactus/io/temporary_path.hpp"

namespace tactus {

AudioWriter::AudioWriter(const std::filesystem::path& path, double sample_rate_hz, int channels)
    : path_(path), temporary_(temporary_path_for(path)), channels_(channels) {
    SF_INFO info{};
    info.samplerate = static_cast<int>(sample_rate_hz);
    info.channels = channels;
    info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
    track_temporary(temporary_);
    file_ = sf_open(temporary_.c_str(), SFM_WRITE, &info);
    if (!file_) {
        const std::string reason = sf_strerror(nullptr);
        discard_temporary(temporary_);
        throw std::runtime_error(fmt::format("{}: cannot write: {}", path.string(), reason));
    }
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
