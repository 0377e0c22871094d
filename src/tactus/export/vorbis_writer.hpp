// Writes an Ogg Vorbis file with any comments (libvorbisenc + libogg), atomically (temporary
// file renamed by commit()). libsndfile writes Ogg Vorbis but only its fixed comment fields
// (title, artist, comment ...), not a named tag such as Android's ANDROID_HAPTIC.
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace tactus {

class VorbisWriter {
  public:
    static constexpr float kQuality =
        0.6f;  // libvorbis VBR quality, -0.1 ... 1 (~ 160 kb/s stereo)

    // comments: (TAG, value) pairs. Throws std::runtime_error naming the file.
    VorbisWriter(const std::filesystem::path& path, double sample_rate_hz, int channels,
                 const std::vector<std::pair<std::string, std::string>>& comments);
    ~VorbisWriter();
    VorbisWriter(const VorbisWriter&) = delete;
    VorbisWriter& operator=(const VorbisWriter&) = delete;

    // channels[c][0 ... frames) for every channel.
    void write(const float* const* channels, int frames);
    void commit();

  private:
    struct State;
    void flush_pages(bool all);
    std::filesystem::path path_, temporary_;
    std::FILE* file_ = nullptr;
    int channels_ = 0;
    std::unique_ptr<State> state_;
};

}  // namespace tactus
