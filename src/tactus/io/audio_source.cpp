#include "tactus/io/audio_source.hpp"

#include <algorithm>

namespace tactus {

FileSource::FileSource(const std::filesystem::path& path, int max_block)
    : reader_(path), max_block_(max_block), name_(path.string()) {
    slots_.reserve(kSlots);
    for (int i = 0; i < kSlots; ++i)
        slots_.push_back({ChannelBlock(reader_.channels(), max_block)});
    at_.resize(static_cast<size_t>(reader_.channels()));
    thread_ = std::thread([this] { decode(); });
}

FileSource::~FileSource() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

// Fills the slots in turn while fewer than kSlots are waiting; stops at the end, an error or the
// destructor.
void FileSource::decode() {
    for (;;) {
        Slot* slot = nullptr;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] { return stop_ || decoded_ - taken_ < kSlots; });
            if (stop_) return;
            slot = &slots_[static_cast<size_t>(decoded_ % kSlots)];
        }
        std::exception_ptr error;
        int frames = 0;
        try {
            frames = reader_.read(slot->block.data(), max_block_);
        } catch (...) {
            error = std::current_exception();
        }
        {
            const std::lock_guard lock(mutex_);
            slot->frames = frames;
            error_ = error;
            ++decoded_;
        }
        changed_.notify_all();
        if (frames == 0) return;
    }
}

int FileSource::next(int max_frames, const float* const*& channels) {
    std::unique_lock lock(mutex_);
    Slot* slot = &slots_[static_cast<size_t>(taken_ % kSlots)];
    if (offset_ > 0 && offset_ >= slot->frames) {  // the current slot is used up: free it
        ++taken_, offset_ = 0;
        changed_.notify_all();
        slot = &slots_[static_cast<size_t>(taken_ % kSlots)];
    }
    changed_.wait(lock, [&] { return decoded_ > taken_; });
    if (slot->frames == 0) {
        if (error_) std::rethrow_exception(error_);
        return 0;
    }
    const int count = std::min({max_frames, max_block_, slot->frames - offset_});
    for (size_t c = 0; c < at_.size(); ++c) at_[c] = slot->block.data()[c] + offset_;
    offset_ += count;
    channels = at_.data();
    return count;
}

int BufferSource::next(int max_frames, const float* const*& channels) {
    const int count = static_cast<int>(std::min<int64_t>(max_frames, frames_ - done_));
    for (size_t c = 0; c < channels_.size(); ++c) at_[c] = channels_[c] + done_;
    done_ += count;
    channels = at_.data();
    return count;
}

}  // namespace tactus
