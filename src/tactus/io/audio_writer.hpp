// Writes a float WAV with N channels, atomically: audio goes to a temporary file in the target directory, renamed over the
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

    // channels[c][0 ... frames) for every channel.
    void write(const float* const* channels, int frames);
    // One channel (a writer opened with 1 channel).
    void write(const float* mono, int frames) { write(&mono, frames); }
    void commit();

  private:
    std::filesystem::path path_, temporary_;
    SNDFILE* file_ = nullptr;
    int channels_ = 1;
    std::vector<float> interleaved_;
};

}  // namespace tactus
