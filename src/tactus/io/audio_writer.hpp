// Writes a float WAV with N identical channels (the paper drives every tonehole with one
// signal), atomically: audio goes to a temporary file in the target directory, renamed over the
// target only by commit(). Destroying an uncommitted writer deletes the temporary file, so a
// failed run leaves nothing behind.
#pragma once

#include <sndfile.h>

#include <filesystem>
#include <vector>

namespace tactus {

class AudioWriter {
  public:
    AudioWriter(const std::filesystem::path& path, double sample_rate_hz, int channels);
    ~AudioWriter();
    AudioWriter(const AudioWriter&) = delete;
    AudioWriter& operator=(const AudioWriter&) = delete;

    void write(const float* mono, int frames);
    void commit();

  private:
    std::filesystem::path path_, temporary_;
    SNDFILE* file_ = nullptr;
    int channels_ = 1;
    std::vector<float> interleaved_;
};

}  // namespace tactus
