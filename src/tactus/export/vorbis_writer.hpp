// Ogg Vorbis with any comments (libvorbisenc + libogg): an encoder that hands its pages to a
// sink, a writer of files on it (atomically: temporary file renamed by commit()), and the bytes
// of a mono file in memory (a page's player). libsndfile writes Ogg Vorbis but only its fixed
// comment fields (title, artist, comment ...), not a named tag such as Android's ANDROID_HAPTIC.
// Offline threads.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tactus {

using VorbisComments = std::vector<std::pair<std::string, std::string>>;  // (TAG, value)

class VorbisEncoder {
  public:
    using Sink = std::function<void(const unsigned char* bytes, size_t count)>;
    // Throws std::runtime_error when Vorbis cannot encode that rate and channel count. `quality`:
    // libvorbis VBR quality, -0.1 ... 1. The headers go to `sink` at once.
    VorbisEncoder(double sample_rate_hz, int channels, const VorbisComments& comments,
                  float quality, Sink sink);
    ~VorbisEncoder();
    VorbisEncoder(const VorbisEncoder&) = delete;
    VorbisEncoder& operator=(const VorbisEncoder&) = delete;

    // channels[c][0 ... frames) for every channel.
    void write(const float* const* channels, int frames);
    // Ends the stream: the last pages go to the sink.
    void finish();

  private:
    struct State;
    void flush_pages(bool all);
    int channels_ = 0;
    Sink sink_;
    std::unique_ptr<State> state_;
};

class VorbisWriter {
  public:
    static constexpr float kQuality = 0.6f;  // ~ 160 kb/s stereo

    // Throws std::runtime_error naming the file.
    VorbisWriter(const std::filesystem::path& path, double sample_rate_hz, int channels,
                 const VorbisComments& comments);
    ~VorbisWriter();
    VorbisWriter(const VorbisWriter&) = delete;
    VorbisWriter& operator=(const VorbisWriter&) = delete;

    void write(const float* const* channels, int frames);
    void commit();

  private:
    std::filesystem::path path_, temporary_;
    std::FILE* file_ = nullptr;
    std::unique_ptr<VorbisEncoder> encoder_;
};

// A mono Ogg Vorbis file in memory, at `quality`; throws std::runtime_error as VorbisEncoder.
std::string vorbis_file_bytes(const std::vector<float>& mono, double sample_rate_hz, float quality);

}  // namespace tactus
