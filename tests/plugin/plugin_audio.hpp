// What the plugin tests share: a sound file as channel buffers, `tactus render` of it through
// the command line, and the comparisons (largest difference, largest step).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "tactus/io/audio_reader.hpp"

namespace tactus::test {

// Sonic Pi's Amen break (stereo, 44.1 kHz, 1.75 s): drums, as the plugin hears them.
inline const std::filesystem::path kDrums = "/usr/share/sonic-pi/samples/loop_amen.flac";

struct Sound {
    std::vector<std::vector<float>> channels;
    double sample_rate_hz = 0;
    size_t frames() const { return channels.empty() ? 0 : channels[0].size(); }
};

inline Sound read_sound(const std::filesystem::path& path) {
    AudioReader reader(path);
    Sound sound;
    sound.sample_rate_hz = reader.sample_rate_hz();
    sound.channels.resize(static_cast<size_t>(reader.channels()));
    ChannelBlock block(reader.channels(), 4096);
    for (int n; (n = reader.read(block.data(), 4096)) > 0;)
        for (int c = 0; c < reader.channels(); ++c)
            sound.channels[static_cast<size_t>(c)].insert(
                sound.channels[static_cast<size_t>(c)].end(), block[c], block[c] + n);
    return sound;
}

// `tactus render`'s output as a host plays it: the input's length. The command rings the
// vibration's tail out past the input's end; a host stops with the input.
inline Sound as_hosts_play(Sound rendered, size_t input_frames) {
    for (auto& channel : rendered.channels) {
        EXPECT_GE(channel.size(), input_frames);
        channel.resize(std::min(channel.size(), input_frames));
    }
    return rendered;
}

inline double max_difference(const std::vector<float>& a, const std::vector<float>& b,
                             size_t from = 0) {
    double d = a.size() == b.size() ? 0.0 : INFINITY;
    for (size_t i = from; i < std::min(a.size(), b.size()); ++i)
        d = std::max(d, std::abs(static_cast<double>(a[i]) - b[i]));
    return d;
}

// Each of the first `actuators` outputs is `vibration` within 1e-5 (each difference printed,
// named by `host`).
inline void expect_each_actuator_is(const std::vector<std::vector<float>>& out, int actuators,
                                    const std::vector<float>& vibration, const char* host) {
    for (int k = 0; k < actuators; ++k) {
        const double d = max_difference(out[static_cast<size_t>(k)], vibration);
        std::printf("%s vibration %d vs tactus render: largest difference %.3g\n", host, k + 1, d);
        EXPECT_LE(d, 1e-5);
    }
}

// The largest sample-to-sample step in [from, to).
inline double max_step(const std::vector<float>& x, size_t from, size_t to) {
    double step = 0;
    for (size_t i = std::max<size_t>(from, 1); i < std::min(to, x.size()); ++i)
        step = std::max(step, std::abs(static_cast<double>(x[i]) - x[i - 1]));
    return step;
}

}  // namespace tactus::test
