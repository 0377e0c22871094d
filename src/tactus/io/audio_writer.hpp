// Writes a sound file with N channels, atomically: audio goes to a temporary file (beside the
// target, or in the temporary directory for stdout, a device or a pipe), renamed over the
// target (or copied into it) only by commit(). Destroying an uncommitted writer deletes the
// temporary file, so a failed run leaves nothing behind. The container is the path's extension
// (.wav, .flac, .ogg, .mp3, .aiff, .w64, .rf64, .caf, .au; "-", stdout, is WAV), with a sample
// format of choice where the container has one.
#pragma once

#include <sndfile.h>

#include <filesystem>
#include <string>
#include <vector>

namespace tactus {

// automatic: float for uncompressed containers, 24-bit for FLAC, none for Vorbis and MP3.
enum class SampleFormat { automatic, pcm16, pcm24, float32 };

// The libsndfile format for writing `path` with `sample`; throws std::runtime_error naming the
// file for an extension libsndfile cannot write or a sample format its container cannot hold.
int writable_sound_format(const std::filesystem::path& path, SampleFormat sample);
// The extensions writable_sound_format accepts, for messages: ".wav, .flac, ...".
std::string writable_sound_extensions();

// Strings stored in the file: WAV INFO chunk (ISFT, ICMT), Vorbis/FLAC comments, ID3 for MP3.
struct SoundTags {
    std::string software, comment;
};

class AudioWriter {
  public:
    AudioWriter(const std::filesystem::path& path, double sample_rate_hz, int channels,
                SampleFormat sample = SampleFormat::automatic, const SoundTags& tags = {});
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
