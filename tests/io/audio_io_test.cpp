// Audio and text I/O: AudioWriter writes float WAV with N identical channels only on commit()
// (atomic rename; an uncommitted writer leaves nothing behind), AudioReader reads any channel
// count as the channel average and names the file in errors; TextOutput likewise; the
// temporary name sits beside the target.
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sndfile.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/signals.hpp"
#include "support/sound_file.hpp"
#include "support/temp_dir.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/audio_writer.hpp"
#include "tactus/io/temporary_path.hpp"
#include "tactus/io/text_output.hpp"

namespace tactus {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class IoTest : public test::TempDirTest {
  protected:
    size_t files_in_dir() const {
        return static_cast<size_t>(std::distance(fs::directory_iterator(dir_), {}));
    }
    static std::vector<float> read_all(const fs::path& path) { return read_mono(path).samples; }
};

TEST_F(IoTest, WriterCommitsAtomicallyAndReaderRoundTrips) {
    const fs::path path = dir_ / "out.wav";
    const std::vector<float> x = test::white_noise(10000, 1, 0.9);
    std::vector<float> negated(x.size()), halved(x.size());
    for (size_t i = 0; i < x.size(); ++i) negated[i] = -x[i], halved[i] = 0.5f * x[i];
    {
        AudioWriter writer(path, 44100, 3);
        const float* first[] = {x.data(), negated.data(), halved.data()};
        const float* rest[] = {x.data() + 4000, negated.data() + 4000, halved.data() + 4000};
        writer.write(first, 4000);
        writer.write(rest, 6000);
        EXPECT_FALSE(fs::exists(path)) << "visible before commit";
        EXPECT_TRUE(fs::exists(temporary_path_for(path)));
        writer.commit();
    }
    ASSERT_TRUE(fs::exists(path));
    EXPECT_FALSE(fs::exists(temporary_path_for(path)));
    EXPECT_EQ(files_in_dir(), 1u);
    AudioReader reader(path);
    EXPECT_EQ(reader.sample_rate_hz(), 44100);
    EXPECT_EQ(reader.channels(), 3);
    EXPECT_EQ(reader.frames(), 10000);
    ChannelBlock block(3, 10000);  // each channel as written, bit for bit
    ASSERT_EQ(reader.read(block.data(), 10000), 10000);
    EXPECT_TRUE(std::equal(x.begin(), x.end(), block[0]));
    EXPECT_TRUE(std::equal(negated.begin(), negated.end(), block[1]));
    EXPECT_TRUE(std::equal(halved.begin(), halved.end(), block[2]));
    const std::vector<float> mono = read_all(path);  // their mean
    ASSERT_EQ(mono.size(), x.size());
    for (size_t i = 0; i < x.size(); ++i) ASSERT_NEAR(mono[i], halved[i] / 3.0f, 1e-7) << i;
}

TEST_F(IoTest, UncommittedWriterLeavesNothing) {
    const fs::path path = dir_ / "never.wav";
    {
        AudioWriter writer(path, 48000, 1);
        const std::vector<float> x(100, 0.5f);
        writer.write(x.data(), 100);
    }
    EXPECT_FALSE(fs::exists(path));
    EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(IoTest, CommitReplacesAnExistingFile) {
    const fs::path path = dir_ / "out.wav";
    std::ofstream(path) << "old";
    AudioWriter writer(path, 8000, 1);
    const std::vector<float> x(50, 0.25f);
    writer.write(x.data(), 50);
    writer.commit();
    EXPECT_EQ(read_all(path), x);
}

TEST_F(IoTest, ReaderAveragesChannels) {
    const fs::path path = dir_ / "stereo.wav";
    std::vector<float> interleaved;
    for (int i = 0; i < 3000; ++i) {
        interleaved.push_back(0.5f);
        interleaved.push_back(static_cast<float>(i % 10) * 0.1f - 0.5f);
    }
    ASSERT_NO_FATAL_FAILURE(
        test::write_sound_file(path, interleaved, 48000, 2, SF_FORMAT_WAV | SF_FORMAT_FLOAT));
    const std::vector<float> mono = read_all(path);
    ASSERT_EQ(mono.size(), 3000u);
    for (int i = 0; i < 3000; ++i)
        ASSERT_FLOAT_EQ(mono[i], 0.5f * (interleaved[2 * i] + interleaved[2 * i + 1])) << i;
}

TEST_F(IoTest, ReaderErrorsNameTheFile) {
    const fs::path missing = dir_ / "missing.wav";
    try {
        AudioReader reader(missing);
        ADD_FAILURE() << "opened a missing file";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr(missing.string()));
    }
    const fs::path junk = dir_ / "junk.wav";
    std::ofstream(junk) << "this is not audio";
    EXPECT_THROW(AudioReader{junk}, std::runtime_error);
}

TEST_F(IoTest, WriterErrorsNameTheFile) {
    const fs::path path = dir_ / "no-such-dir" / "out.wav";
    try {
        AudioWriter writer(path, 48000, 1);
        ADD_FAILURE() << "wrote into a missing directory";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr(path.string()));
    }
}

TEST_F(IoTest, TemporaryPathIsHiddenBesideTheTarget) {
    const fs::path target = dir_ / "name.txt";
    const fs::path temporary = temporary_path_for(target);
    EXPECT_EQ(temporary.parent_path(), dir_);
    EXPECT_EQ(temporary.filename().string(), ".name.txt.tmp-" + std::to_string(::getpid()));
}

TEST_F(IoTest, CommitTemporaryFailureRemovesTheTemporary) {
    const fs::path temporary = dir_ / ".x.tmp";
    std::ofstream(temporary) << "data";
    const fs::path target = dir_ / "missing-dir" / "x";
    EXPECT_THROW(commit_temporary(temporary, target), std::runtime_error);
    EXPECT_FALSE(fs::exists(temporary));
}

TEST_F(IoTest, TextOutputCommitsAtomically) {
    const fs::path path = dir_ / "onsets.txt";
    {
        TextOutput out(path);
        out.stream() << "0.25\n0.5\n";
        EXPECT_FALSE(fs::exists(path));
        out.commit();
    }
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str(), "0.25\n0.5\n");
    EXPECT_EQ(files_in_dir(), 1u);
    {
        TextOutput abandoned(dir_ / "abandoned.txt");
        abandoned.stream() << "x";
    }
    EXPECT_FALSE(fs::exists(dir_ / "abandoned.txt"));
    EXPECT_EQ(files_in_dir(), 1u);
}

TEST_F(IoTest, TextOutputDashIsStdout) {
    TextOutput out("-");
    EXPECT_EQ(&out.stream(), &std::cout);
    TextOutput empty("");
    EXPECT_EQ(&empty.stream(), &std::cout);
    EXPECT_NO_THROW(out.commit());
    EXPECT_EQ(files_in_dir(), 0u);
}

TEST_F(IoTest, ReaderRefusesATruncatedWavAndAnEmptyFile) {
    const fs::path whole = dir_ / "whole.wav";
    {
        AudioWriter writer(whole, 48000, 2);
        const auto x = test::white_noise(48000, 3, 0.5);
        const float* channels[] = {x.data(), x.data()};
        writer.write(channels, static_cast<int>(x.size()));
        writer.commit();
    }
    const fs::path cut = dir_ / "cut.wav";
    fs::copy_file(whole, cut);
    fs::resize_file(cut, fs::file_size(whole) - 1000);
    try {
        AudioReader reader(cut);
        ADD_FAILURE() << "opened a truncated file";
    } catch (const std::runtime_error& e) {
        EXPECT_THAT(e.what(), HasSubstr(cut.string() + ": truncated: the header announces"));
    }
    std::ofstream(dir_ / "empty.wav").close();
    EXPECT_THROW(AudioReader{dir_ / "empty.wav"}, std::runtime_error);
}

// Writers track their temporaries for the signal handler and release them on commit or
// destruction, so a long batch never runs out of slots; too many at once is an error.
TEST_F(IoTest, TemporariesAreTrackedAndReleased) {
    for (int i = 0; i < 3 * kMaxTrackedTemporaries; ++i) {
        AudioWriter writer(dir_ / fmt::format("{}.wav", i % 4), 8000, 1);
        if (i % 2) writer.commit();
    }
    std::vector<std::unique_ptr<TextOutput>> open;
    for (int i = 0; i < kMaxTrackedTemporaries; ++i)
        open.push_back(std::make_unique<TextOutput>(dir_ / fmt::format("t{}.txt", i)));
    EXPECT_THROW(TextOutput(dir_ / "one-too-many.txt"), std::runtime_error);
    open.clear();
    EXPECT_NO_THROW(TextOutput(dir_ / "fits-again.txt"));
    expect_no_temporaries();
}

}  // namespace
}  // namespace tactus
