// Audio files made and inspected with libsndfile directly, independent of the library's
// AudioWriter / AudioReader: for inputs the library never writes (other formats and subtypes,
// channels that differ) and for checking what it wrote.
#pragma once

#include <gtest/gtest.h>
#include <sndfile.h>

#include <filesystem>
#include <vector>

namespace tactus::test {

// Writes `interleaved` (frames of `channels` samples) to `path` as `format` (major format |
// subtype) at `rate`. A file libsndfile cannot open is a fatal failure of this function: callers
// that must stop there wrap the call in ASSERT_NO_FATAL_FAILURE.
inline void write_sound_file(const std::filesystem::path& path,
                             const std::vector<float>& interleaved, double rate, int channels = 1,
                             int format = SF_FORMAT_WAV | SF_FORMAT_FLOAT) {
    SF_INFO info{};
    info.samplerate = static_cast<int>(rate);
    info.channels = channels;
    info.format = format;
    SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
    ASSERT_NE(file, nullptr) << sf_strerror(nullptr);
    sf_writef_float(file, interleaved.data(),
                    static_cast<sf_count_t>(interleaved.size() / static_cast<size_t>(channels)));
    sf_close(file);
}

// The header of an audio file (all zero if it cannot be opened).
inline SF_INFO info_of(const std::filesystem::path& path) {
    SF_INFO info{};
    SNDFILE* f = sf_open(path.c_str(), SFM_READ, &info);
    if (f) sf_close(f);
    return info;
}

// A render is its input plus the vibration's tail (io/run_file.hpp, RunTail::ring_out): at least
// the limiter's look-ahead longer, and never more than the last pulse's decay (150 ms under tfd)
// and the silence that ends it later: within half a second.
inline void expect_input_plus_tail(int64_t rendered_frames, int64_t input_frames,
                                   double sample_rate_hz) {
    EXPECT_GT(rendered_frames, input_frames);
    EXPECT_LT(rendered_frames, input_frames + static_cast<int64_t>(0.5 * sample_rate_hz));
}

}  // namespace tactus::test
