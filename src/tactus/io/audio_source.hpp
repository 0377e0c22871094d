// Where the offline run loop (run_file.hpp) takes its audio from: a file read in blocks through
// libsndfile (FileSource, constant memory), or audio already in memory (BufferSource: a view of
// one array per channel, nothing copied). One loop for both, so a file and the same samples in
// memory give the same output, bit for bit. Setup thread only: next() may wait for a file.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "tactus/io/audio_reader.hpp"

namespace tactus {

class AudioSource {
  public:
    virtual ~AudioSource() = default;
    virtual double sample_rate_hz() const = 0;
    virtual int channels() const = 0;
    // The frames it holds, or <= 0 when unknown (progress only: the loop reads to the end).
    virtual int64_t frames() const = 0;
    // What errors name it by: the file's path, or what the caller calls the buffer.
    virtual const std::string& name() const = 0;
    // Up to max_frames next frames, one pointer per channel in `channels`, valid until the
    // next call; returns how many (0 at the end).
    virtual int next(int max_frames, const float* const*& channels) = 0;
};

// A file, decoded block by block into buffers of `max_block` frames on a thread of its own, a
// few blocks ahead of next(), so that decoding (a FLAC's or an MP3's: as long as the whole
// analysis) runs beside the engine instead of before it. The blocks and an error are handed on in
// the file's order: a read that fails throws from next() once the blocks before it are taken.
class FileSource final : public AudioSource {
  public:
    // Throws std::runtime_error naming the file when it cannot be opened.
    FileSource(const std::filesystem::path& path, int max_block);
    ~FileSource() override;
    FileSource(const FileSource&) = delete;
    FileSource& operator=(const FileSource&) = delete;
    double sample_rate_hz() const override { return reader_.sample_rate_hz(); }
    int channels() const override { return reader_.channels(); }
    int64_t frames() const override { return reader_.frames(); }
    const std::string& name() const override { return name_; }
    int next(int max_frames, const float* const*& channels) override;

  private:
    static constexpr int kSlots = 3;  // blocks decoded ahead, and the one being taken
    struct Slot {
        ChannelBlock block;
        int frames = 0;  // decoded into it; 0: the end (or the error)
    };
    void decode();  // the decoding thread

    AudioReader reader_;
    int max_block_;
    std::string name_;
    std::vector<Slot> slots_;
    std::vector<const float*> at_;  // the channels of what next() handed on
    std::mutex mutex_;
    std::condition_variable changed_;
    int64_t decoded_ = 0, taken_ = 0;  // slots filled, and handed on in full, since the start
    int offset_ = 0;  // frames of the current slot already handed on (> 0: it is in use)
    bool stop_ = false;
    std::exception_ptr error_;  // what the read after the last filled slot threw
    std::thread thread_;
};

// channels[c][0 ... frames) at `sample_rate_hz`, read where they are (kept alive by the
// caller).
class BufferSource final : public AudioSource {
  public:
    BufferSource(std::vector<const float*> channels, int64_t frames, double sample_rate_hz,
                 std::string name)
        : channels_(std::move(channels)),
          at_(channels_.size()),
          frames_(frames),
          sample_rate_hz_(sample_rate_hz),
          name_(std::move(name)) {}
    double sample_rate_hz() const override { return sample_rate_hz_; }
    int channels() const override { return static_cast<int>(channels_.size()); }
    int64_t frames() const override { return frames_; }
    const std::string& name() const override { return name_; }
    int next(int max_frames, const float* const*& channels) override;

  private:
    std::vector<const float*> channels_, at_;
    int64_t frames_, done_ = 0;
    double sample_rate_hz_;
    std::string name_;
};

}  // namespace tactus
