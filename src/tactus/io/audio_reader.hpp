// Streams any file libsndfile reads (WAV, AIFF, FLAC, OGG, MP3, ...) as float blocks, one
// buffer per channel (the engine downmixes). Constant memory whatever the length.
#pragma once

#include <sndfile.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tactus {

class AudioReader {
  public:
    // Throws std::runtime_error naming the file and what is wrong.
    explicit AudioReader(const std::filesystem::path& path);
    ~AudioReader();
    AudioReader(const AudioReader&) = delete;
    AudioReader& operator=(const AudioReader&) = delete;

    double sample_rate_hz() const { return info_.samplerate; }
    int channels() const { return info_.channels; }
    // May be unknown (<= 0) for some formats, and is an estimate for an MP3 without a length
    // tag (mpeg_length_tag.hpp): the stream is read to its end, whatever its length.
    int64_t frames() const { return info_.frames; }
    // The file's comment (WAV ICMT, Vorbis COMMENT: render writes RenderInfo::comment()), or "".
    std::string comment() const {
        const char* text = sf_get_string(file_, SF_STR_COMMENT);
        return text ? text : "";
    }
    // Reads up to `max_frames` frames into channels()[c][0 ... max_frames); returns how many
    // (0 at the end). Throws std::runtime_error for undecodable data or a stream that ends
    // before the length its header or tag states.
    int read(float* const* channels, int max_frames);

  private:
    std::filesystem::path path_;
    SNDFILE* file_ = nullptr;
    SF_INFO info_{};
    std::vector<float> interleaved_;
    std::vector<short> pcm16_;
    int64_t frames_read_ = 0;
    bool length_stated_ = true;  // info_.frames is the file's statement, not an estimate
};

// Buffers for `channels` channels of `frames` samples, as AudioReader::read and
// Engine::process take them.
class ChannelBlock {
  public:
    ChannelBlock(int channels, int frames);
    float* const* data() { return pointers_.data(); }
    const float* const* data() const { return pointers_.data(); }
    float* operator[](int channel) { return pointers_[static_cast<size_t>(channel)]; }

  private:
    std::vector<float> samples_;
    std::vector<float*> pointers_;
};

// A whole file as mono samples (the channels' mean), for tools and tests; streaming code uses
// AudioReader.
struct MonoAudio {
    std::vector<float> samples;
    double sample_rate_hz = 0;
};
MonoAudio read_mono(const std::filesystem::path& path);

}  // namespace tactus
