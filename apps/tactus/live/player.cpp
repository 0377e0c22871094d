#include "player.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tactus/dsp/resampler.hpp"
#include "tactus/io/audio_reader.hpp"

namespace tactus::live {

namespace {

constexpr int kChunk = 65536;  // frames decoded or converted at a time

// x at `from_hz`, as the same sound at `to_hz` (setup thread).
std::vector<float> converted(const std::vector<float>& x, double from_hz, double to_hz) {
    Resampler r;
    r.prepare(from_hz, to_hz, kChunk, Resampler::Band::listening);
    const double ratio = static_cast<double>(r.up()) / static_cast<double>(r.down());
    const auto frames = static_cast<size_t>(std::llround(static_cast<double>(x.size()) * ratio));
    std::vector<float> y, out(static_cast<size_t>(std::ceil(kChunk * ratio)) + 1);
    const std::vector<float> tail(static_cast<size_t>(r.taps()), 0.0f);  // the last outputs' input
    const auto feed = [&](const float* in, size_t count) {
        for (size_t done = 0; done < count;) {
            const int n = static_cast<int>(std::min<size_t>(count - done, kChunk));
            const int made = r.process(in + done, n, out.data());
            y.insert(y.end(), out.begin(), out.begin() + made);
            done += static_cast<size_t>(n);
        }
    };
    feed(x.data(), x.size());
    while (y.size() < frames) feed(tail.data(), tail.size());
    y.resize(frames);
    return y;
}

}  // namespace

Player::Player(const std::vector<std::filesystem::path>& files, double sample_rate_hz, bool loop)
    : loop_(loop) {
    if (files.empty()) throw std::runtime_error("play: no file");
    for (const auto& file : files) {
        AudioReader reader(file);
        if (channels_ == 0) {
            channels_ = reader.channels();
            samples_.resize(static_cast<size_t>(channels_));
        } else if (reader.channels() != channels_) {
            throw std::runtime_error(fmt::format("{}: {} channels, but the first file has {}",
                                                 file.string(), reader.channels(), channels_));
        }
        std::vector<std::vector<float>> decoded(static_cast<size_t>(channels_)),
            chunk(static_cast<size_t>(channels_), std::vector<float>(kChunk));
        std::vector<float*> pointers;
        pointers.reserve(chunk.size());
        for (auto& c : chunk) pointers.push_back(c.data());
        while (const int n = reader.read(pointers.data(), kChunk))
            for (size_t c = 0; c < decoded.size(); ++c)
                decoded[c].insert(decoded[c].end(), chunk[c].begin(), chunk[c].begin() + n);
        if (reader.sample_rate_hz() != sample_rate_hz) {
            for (auto& d : decoded) d = converted(d, reader.sample_rate_hz(), sample_rate_hz);
            conversions_.push_back(fmt::format("{}: {:g} Hz, converted to the device's {:g} Hz",
                                               file.string(), reader.sample_rate_hz(),
                                               sample_rate_hz));
        }
        for (size_t c = 0; c < decoded.size(); ++c)
            samples_[c].insert(samples_[c].end(), decoded[c].begin(), decoded[c].end());
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
