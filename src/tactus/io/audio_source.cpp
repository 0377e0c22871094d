#include "tactus/io/audio_source.hpp"

#include <algorithm>

namespace tactus {

FileSource::FileSource(const std::filesystem::path& path, int max_block)
    : reader_(path),
      block_(reader_.channels(), max_block),
      max_block_(max_block),
      name_(path.string()) {}

int FileSource::next(int max_frames, const float* const*& channels) {
    channels = block_.data();
    return reader_.read(block_.data(), std::min(max_frames, max_block_));
}

int BufferSource::next(int max_frames, const float* const*& channels) {
    const int count = static_cast<int>(std::min<int64_t>(max_frames, frames_ - done_));
    for (size_t c = 0; c < channels_.size(); ++c) at_[c] = channels_[c] + done_;
    done_ += count;
    channels = at_.data();
    return count;
}

}  // namespace tactus
