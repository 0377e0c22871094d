// The player of `tactus live --play`: the paper's second display mode (§6, the Tactilicious Flute
// Display playing breakbeats), where a file is both the sound and the source of the vibration.
// Files are decoded whole into memory on the setup thread, so the audio thread only copies; a
// file at another rate than the device's is converted to it there (dsp/resampler.hpp,
// Band::listening), so the engine hears what is played.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tactus::live {

class Player {
  public:
    // Setup thread: decodes every file (each must have the first file's channel count),
    // converting those at another rate to `sample_rate_hz`; throws std::runtime_error naming the
    // file.
    Player(const std::vector<std::filesystem::path>& files, double sample_rate_hz, bool loop);
    // One line for each file converted: its name and rate.
    const std::vector<std::string>& conversions() const { return conversions_; }
    // The files' rate, when the device rate follows it.
    static double sample_rate_of(const std::filesystem::path& file);

    int channels() const { return channels_; }
    int64_t frames() const {
        return static_cast<int64_t>(samples_.empty() ? 0 : samples_[0].size());
    }

    // Audio thread: the next `count` frames into channels[0 .. channels()), silence once the
    // files are done (never, with loop).
    void read(float* const* channels, int count) noexcept;
    // Any thread: every frame has been read (never, with loop).
    bool finished() const { return finished_.load(std::memory_order_relaxed); }

  private:
    std::vector<std::vector<float>> samples_;  // the files one after another, per channel
    std::vector<std::string> conversions_;
    int channels_ = 0;
    bool loop_ = false;
    int64_t position_ = 0;
    std::atomic<bool> finished_{false};
};

}  // namespace tactus::live
