// FileSource decodes ahead on a thread of its own (io/audio_source.hpp): with the engine's
// threaded tests, so that make test-tsan runs it under ThreadSanitizer.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "support/signals.hpp"
#include "support/sound_file.hpp"
#include "support/temp_dir.hpp"
#include "tactus/io/audio_source.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using FileSourceTest = test::TempDirTest;

// FileSource decodes ahead on a thread of its own: what next() hands on, in pieces of any size,
// is the file's samples in order; a FLAC cut short hands on what decodes, then throws naming the
// file; a source dropped halfway stops its thread.
TEST_F(FileSourceTest, HandsOnTheFileInOrderThenItsError) {
    const double fs = 44100;
    const auto x = test::white_noise(static_cast<size_t>(3 * fs), 5, 0.5);
    const fs::path wav = dir_ / "noise.wav";
    test::write_sound_file(wav, x, fs);
    FileSource source(wav, 1000);
    std::vector<float> read;
    const float* const* channels = nullptr;
    for (int piece = 1;; piece = piece % 1500 + 377) {
        const int got = source.next(piece, channels);
        if (got == 0) break;
        EXPECT_LE(got, std::min(piece, 1000));
        read.insert(read.end(), channels[0], channels[0] + got);
    }
    EXPECT_EQ(read, x);
    EXPECT_EQ(source.next(1000, channels), 0);

    const fs::path flac = dir_ / "noise.flac";
    test::write_sound_file(flac, x, fs, 1, SF_FORMAT_FLAC | SF_FORMAT_PCM_16);
    const fs::path cut = dir_ / "cut.flac";
    fs::copy_file(flac, cut);
    fs::resize_file(cut, fs::file_size(flac) / 2);
    FileSource truncated(cut, 4096);
    int64_t frames = 0;
    try {
        while (const int got = truncated.next(4096, channels)) frames += got;
        ADD_FAILURE() << "read a truncated FLAC to its end";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr(cut.string() + ": corrupt or truncated audio data"));
    }
    EXPECT_GT(frames, 0);
    EXPECT_LT(frames, static_cast<int64_t>(x.size()));

    FileSource dropped(wav, 64);
    EXPECT_EQ(dropped.next(64, channels), 64);
}

}  // namespace
}  // namespace tactus
