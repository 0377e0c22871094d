#include "player.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "tactus/io/audio_reader.hpp"

namespace tactus::live {

Player::Player(const std::vector<std::filesystem::path>& files, double sample_rate_hz, bool loop)
    : loop_(loop) {
    if (files.empty()) throw std::runtime_error("play: no file");
    for (const auto& file : files) {
        AudioReader reader(file);
        if (reader.sample_rate_hz() != sample_rate_hz)
            throw std::runtime_error(fmt::format(
                "{}: its rate is {:g} Hz but the device runs at {:g} Hz (give --rate {:g}, or "
                "convert the file)",
                file.string(), reader.sample_rate_hz(), sample_rate_hz, reader.sample_rate_hz()));
        if (channels_ == 0) {
            channels_ = reader.channels();
            samples_.resize(static_cast<size_t>(channels_));
        } else if (reader.channels() != channels_) {
            throw std::runtime_error(fmt::format("{}: {} channels, but the first file has {}",
                                                 file.string(), reader.channels(), channels_));
        }
        constexpr int kChunk = 65536;
        std::vector<std::vector<float>> chunk(static_cast<size_t>(channels_),
                                              std::vector<float>(kChunk));
        std::vector<float*> pointers;
        for (auto& c : chunk) pointers.push_back(c.data());
        while (const int n = reader.read(pointers.data(), kChunk))
            for (int c = 0; c < channels_; ++c)
                samples_[static_cast<size_t>(c)].insert(samples_[static_cast<size_t>(c)].end(),
                                                        chunk[static_cast<size_t>(c)].begin(),
                                                        chunk[static_cast<size_t>(c)].begin() + n);
    }
    if (frames() == 0) throw std::runtime_error(fmt::format("{}: no audio", files[0].string()));
}

double Player::sample_rate_of(const std::filesystem::path& file) {
    return AudioReader(file).sample_rate_hz();
}

void Player::read(float* const* channels, int count) noexcept {
    const int64_t total = frames();
    int done = 0;
    while (done < count) {
        if (position_ >= total) {
            if (!loop_) {
                for (int c = 0; c < channels_; ++c)
                    std::fill(channels[c] + done, channels[c] + count, 0.0f);
                finished_.store(true, std::memory_order_relaxed);
                return;
            }
            position_ = 0;
        }
        const int n = static_cast<int>(std::min<int64_t>(count - done, total - position_));
        for (int c = 0; c < channels_; ++c) {
            const float* from = samples_[static_cast<size_t>(c)].data() + position_;
            std::copy(from, from + n, channels[c] + done);
        }
        position_ += n;
        done += n;
    }
    if (!loop_ && position_ >= total) finished_.store(true, std::memory_order_relaxed);
}

}  // namespace tactus::live
