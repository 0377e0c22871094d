// Streams any file libsndfile reads (WAV, AIFF, FLAC, OGG, MP3, ...) as mono float blocks:
// channels are averaged. Constant memory whatever the length.
#pragma once

#include <sndfile.h>

#include <cstdint>
#include <filesystem>
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
    int64_t frames() const { return info_.frames; }  // may be unknown (<= 0) for some formats
    // Reads up to `max_frames` mono frames; returns how many (0 at the end). Throws
    // std::runtime_error for undecodable data or a stream that ends before its header says.
    int read(float* mono, int max_frames);

  private:
    std::filesystem::path path_;
    SNDFILE* file_ = nullptr;
    SF_INFO info_{};
    std::vector<float> interleaved_;
    std::vector<short> pcm16_;
    int64_t frames_read_ = 0;
};

// A whole file as mono samples, for tools and tests; streaming code uses AudioReader.
struct MonoAudio {
    std::vector<float> samples;
    double sample_rate_hz = 0;
};
MonoAudio read_mono(const std::filesystem::path& path);

}  // namespace tactus
