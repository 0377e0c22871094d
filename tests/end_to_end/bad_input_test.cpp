// Every bad input a user can give the command line, run for real: a one-line error on stderr
// naming the file, line or parameter, a non-zero exit, and nothing lost (no output, no partial
// or temporary file, the input untouched). Bad files are made here from real ones written with
// libsndfile. docs/robustness.md lists each case with its message and the test that checks it.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sndfile.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "support/run_cli.hpp"
#include "support/signals.hpp"
#include "tactus/io/audio_reader.hpp"

namespace {

namespace fs = std::filesystem;
using tactus::test::CliResult;
using tactus::test::csv_numbers;

constexpr double kRate = 44100;

class BadInput : public tactus::test::Cli {
  protected:
    void SetUp() override {
        Cli::SetUp();
        out_ = dir_ / "out.wav";
    }

    // A real audio file: `channels` interleaved channels of `mono` repeated.
    fs::path write_audio(const std::string& name, const std::vector<float>& mono,
                         int format = SF_FORMAT_WAV | SF_FORMAT_PCM_16, double rate = kRate,
                         int channels = 1) const {
        const fs::path path = dir_ / name;
        std::vector<float> interleaved;
        for (const float x : mono) interleaved.insert(interleaved.end(), channels, x);
        tactus::test::write_sound_file(path, interleaved, rate, channels, format);
        return path;
    }
    fs::path drums(const std::string& name, double seconds = 3,
                   int format = SF_FORMAT_WAV | SF_FORMAT_PCM_16) const {
        return write_audio(name, tactus::test::drum_pattern(kRate, seconds, 7).audio, format);
    }
    fs::path write_text(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return dir_ / name;
    }
    // The first `bytes` bytes of `source`, as `name`.
    fs::path truncate(const fs::path& source, const std::string& name, size_t bytes) const {
        std::ifstream in(source, std::ios::binary);
        std::string data(bytes, '\0');
        in.read(data.data(), static_cast<std::streamsize>(bytes));
        return write_text(name, data.substr(0, static_cast<size_t>(in.gcount())));
    }

    // Failed with one line on stderr holding every piece of `expected`, and left no output.
    void expect_refused(const CliResult& r, std::initializer_list<std::string> expected,
                        const fs::path& output) const {
        EXPECT_NE(r.exit_code, 0);
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(r.err.rfind("tactus: error: ", 0), 0u) << r.err;
        for (const auto& piece : expected) EXPECT_NE(r.err.find(piece), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(output)) << output;
        expect_no_temporaries();
    }
    void expect_refused(const CliResult& r, std::initializer_list<std::string> expected) const {
        expect_refused(r, expected, out_);
    }
    CliResult render(const fs::path& input, const std::string& more = "") const {
        return run("render " + input.string() + " -o " + out_.string() + " " + more);
    }
    std::vector<float> rendered() const { return tactus::read_mono(out_).samples; }

    // Runs the CLI as `nobody` when the tests run as root (root ignores file permissions). The
    // repository may sit where `nobody` cannot read (a mode-700 /root), so `nobody` runs a copy of
    // the program and its data installed in the test's own directory, with that directory as home.
    CliResult run_unprivileged(const std::string& arguments) const {
        if (geteuid() != 0) return run(arguments);
        const fs::path bin = dir_ / "bin", data = dir_ / "share" / "tactus";
        fs::create_directories(bin);
        fs::create_directories(data);
        fs::copy_file(TACTUS_CLI, bin / "tactus", fs::copy_options::overwrite_existing);
        const fs::path built_data =
            fs::path(TACTUS_CLI).parent_path().parent_path() / "share" / "tactus";
        for (const char* folder : {"presets", "actuators"})
            fs::copy(built_data / folder, data / folder,
                     fs::copy_options::recursive | fs::copy_options::overwrite_existing);
        for (const fs::path& made : {dir_, bin, dir_ / "share", data})
            fs::permissions(made, fs::perms::all);
        for (const auto& entry : fs::recursive_directory_iterator(data))
            if (entry.is_directory()) fs::permissions(entry.path(), fs::perms::all);
        return run(arguments,
                   "HOME=" + dir_.string() + " setpriv --reuid=65534 --regid=65534 --clear-groups ",
                   bin / "tactus");
    }

    fs::path out_;
};

// --- audio inputs -------------------------------------------------------------------------

// Every command taking input paths says it in one line, in tactus's words, and exits 1 as for
// any error it finds (not 105, CLI11's code); with several inputs, nothing is written.
TEST_F(BadInput, MissingInputFile) {
    const fs::path missing = dir_ / "nosuch.wav";
    const std::string expected =
        "tactus: error: " + missing.string() + ": no such file or directory\n";
    const std::string o = " -o " + out_.string();
    std::vector<std::string> commands = {
        "render " + missing.string() + o,
        "analyze " + missing.string() + o,
        "onsets " + missing.string() + o,
        "meter " + missing.string() + o,
        "simulate " + missing.string() + o,
        "report " + missing.string() + o,
        "export " + missing.string() + " -o " + (dir_ / "out.ahap").string(),
        "placement " + missing.string() + o,
        "render " + drums("here.wav", 1).string() + " " + missing.string() + " -O " +
            (dir_ / "outs").string(),
        "render " + (dir_ / "nowhere" / "nosuch.wav").string() + o};
    if (run("live --help").exit_code == 0)  // built with audio devices
        commands.push_back("live --play " + missing.string() + " --duration 1");
    for (const std::string& command : commands) {
        const CliResult r = run(command);
        EXPECT_EQ(r.exit_code, 1) << command;
        if (command.find("nowhere") != std::string::npos)
            EXPECT_EQ(r.err, "tactus: error: " + (dir_ / "nowhere" / "nosuch.wav").string() +
                                 ": no such file or directory\n");
        else
            EXPECT_EQ(r.err, expected) << command;
        EXPECT_FALSE(fs::exists(out_)) << command;
        EXPECT_FALSE(fs::exists(dir_ / "out.ahap")) << command;
        EXPECT_FALSE(fs::exists(dir_ / "outs")) << command;
    }
    expect_no_temporaries();
}

TEST_F(BadInput, InputIsADirectory) {
    expect_refused(render(dir_), {"directory", dir_.string()});
}

TEST_F(BadInput, UnreadableInputFile) {
    const fs::path input = drums("locked.wav", 1);
    fs::permissions(input, fs::perms::none);
    fs::permissions(dir_, fs::perms::all);
    const CliResult r =
        run_unprivileged("render " + input.string() + " -o " + (dir_ / "x.wav").string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("locked.wav"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("Permission denied"), std::string::npos) << r.err;
}

TEST_F(BadInput, EmptyFile) {
    expect_refused(render(write_text("empty.wav", "")), {"empty.wav: empty file"});
}

TEST_F(BadInput, TextFileNamedWav) {
    expect_refused(render(write_text("notes.wav", "not audio\n")),
                   {"notes.wav: cannot read audio"});
}

TEST_F(BadInput, UnsupportedFormat) {
    std::string bytes = "\x89PNG\r\n\x1a\n";
    for (int i = 0; i < 1000; ++i) bytes += static_cast<char>(i * 37);
    expect_refused(render(write_text("picture.png", bytes)), {"picture.png: cannot read audio"});
}

TEST_F(BadInput, WavHeaderWithoutData) {
    expect_refused(render(truncate(drums("whole.wav"), "header.wav", 30)),
                   {"header.wav: cannot read audio"});
}

TEST_F(BadInput, TruncatedWav) {
    const fs::path whole = drums("whole.wav");
    expect_refused(render(truncate(whole, "cut.wav", fs::file_size(whole) / 2)),
                   {"cut.wav: truncated: the header announces"});
}

TEST_F(BadInput, TruncatedFlac) {
    const fs::path whole = drums("whole.flac", 3, SF_FORMAT_FLAC | SF_FORMAT_PCM_16);
    expect_refused(render(truncate(whole, "cut.flac", fs::file_size(whole) / 2)),
                   {"cut.flac: corrupt or truncated audio data"});
}

TEST_F(BadInput, CorruptFlac) {
    const fs::path whole = drums("whole.flac", 3, SF_FORMAT_FLAC | SF_FORMAT_PCM_16);
    std::ifstream in(whole, std::ios::binary);
    std::string data((std::istreambuf_iterator<char>(in)), {});
    for (size_t i = 4096; i < data.size(); i += 997) data[i] = static_cast<char>(~data[i]);
    expect_refused(render(write_text("corrupt.flac", data)), {"corrupt.flac: corrupt"});
}

TEST_F(BadInput, Mp3IsReadAndTruncatedMp3Refused) {
    const fs::path mp3 = drums("beat.mp3", 3, SF_FORMAT_MPEG | SF_FORMAT_MPEG_LAYER_III);
    ASSERT_EQ(render(mp3).exit_code, 0);
    tactus::test::expect_input_plus_tail(static_cast<int64_t>(rendered().size()),
                                         static_cast<int64_t>(3 * kRate), kRate);
    fs::remove(out_);
    const CliResult r = render(truncate(mp3, "cut.mp3", fs::file_size(mp3) / 2));
    EXPECT_NE(r.exit_code, 0);
    // libmpg123 itself may print a warning line before ours; ours is the last line.
    EXPECT_NE(r.err.find("tactus: error: " + (dir_ / "cut.mp3").string() +
                         ": truncated or corrupt: the header announces"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out_));
    expect_no_temporaries();
}

// A constant-bitrate MP3 without a Xing/Info tag (lame -t; older encoders wrote none) states
// no length: libmpg123 estimates it from the file's size and the first frame's, and its padded
// frames make the estimate exceed what decodes by more than the slack a stated length gets. It
// is read to its end. The same encoding with its Info tag (behind an ID3v2 tag), cut in half,
// is still refused.
TEST_F(BadInput, Mp3WithoutLengthTagIsReadToItsEnd) {
    constexpr double kSeconds = 30;
    const fs::path wav = drums("long.wav", kSeconds), mp3 = dir_ / "cbr.mp3";
    const std::string lame = "lame --quiet -b 128 ";
    ASSERT_EQ(std::system((lame + "-t " + wav.string() + " " + mp3.string()).c_str()), 0)
        << "lame (scripts/setup.sh installs it)";
    int64_t decoded = 0;
    {
        tactus::AudioReader reader(mp3);
        tactus::ChannelBlock block(reader.channels(), 4096);
        while (const int got = reader.read(block.data(), 4096)) decoded += got;
        // The estimate exceeds what decodes by more than two MPEG frames: refused before.
        ASSERT_GT(reader.frames(), decoded + 2 * 1152) << "an estimate the old check refused";
    }
    EXPECT_GT(decoded, static_cast<int64_t>(kSeconds * kRate));  // the whole file (+ delay)
    const CliResult onsets = run("onsets " + mp3.string());
    EXPECT_EQ(onsets.exit_code, 0) << onsets.err;
    EXPECT_EQ(onsets.err, "");
    EXPECT_GT(std::count(onsets.out.begin(), onsets.out.end(), '\n'), 100);
    ASSERT_EQ(render(mp3).exit_code, 0);
    tactus::test::expect_input_plus_tail(static_cast<int64_t>(rendered().size()), decoded, kRate);
    fs::remove(out_);

    const fs::path tagged = dir_ / "tagged.mp3";
    // An ID3v2 tag (5 kB of padding) before the first frame, as tagged music has.
    const std::string id3 = "--add-id3v2 --pad-id3v2-size 5000 --tt beat ";
    ASSERT_EQ(std::system((lame + id3 + wav.string() + " " + tagged.string()).c_str()), 0);
    const CliResult cut = render(truncate(tagged, "cut.mp3", fs::file_size(tagged) / 2));
    EXPECT_NE(cut.exit_code, 0);
    EXPECT_NE(cut.err.find("tactus: error: " + (dir_ / "cut.mp3").string() +
                           ": truncated or corrupt: the header announces"),
              std::string::npos)
        << cut.err;
    EXPECT_FALSE(fs::exists(out_));
    expect_no_temporaries();
}

TEST_F(BadInput, ZeroFrames) {
    expect_refused(render(write_audio("silent.wav", {})), {"silent.wav: no audio frames"});
}

TEST_F(BadInput, SampleRatesOutsideTheSupportedRange) {
    const auto tone = [&](double rate) { return tactus::test::sine(100, rate, 4000, 0.5); };
    for (const double rate : {4000.0, 7999.0, 192001.0, 384000.0})
        expect_refused(
            render(write_audio("tone.wav", tone(rate), SF_FORMAT_WAV | SF_FORMAT_PCM_16, rate)),
            {"tone.wav: sample rate", "outside the supported 8000-192000 Hz"});
    for (const double rate : {8000.0, 192000.0}) {
        EXPECT_EQ(
            render(write_audio("edge.wav", tone(rate), SF_FORMAT_WAV | SF_FORMAT_PCM_16, rate),
                   "--force")
                .exit_code,
            0)
            << rate;
    }
}

TEST_F(BadInput, ManyChannelsAreDownmixed) {
    const auto beat = tactus::test::drum_pattern(kRate, 2, 3).audio;
    for (const int channels : {32, 64, 256}) {
        const fs::path input =
            write_audio("wide.wav", beat, SF_FORMAT_WAV | SF_FORMAT_PCM_16, kRate, channels);
        ASSERT_EQ(render(input, "--force").exit_code, 0) << channels;
        const auto out = rendered();
        tactus::test::expect_input_plus_tail(static_cast<int64_t>(out.size()),
                                             static_cast<int64_t>(beat.size()), kRate);
        EXPECT_GT(tactus::test::rms(out), 0.01) << channels;
    }
}

TEST_F(BadInput, NonFiniteAndDenormalSamplesNeverReachTheOutput) {
    auto audio = tactus::test::drum_pattern(kRate, 3, 5).audio;
    const float bad[] = {std::numeric_limits<float>::quiet_NaN(),
                         std::numeric_limits<float>::infinity(),
                         -std::numeric_limits<float>::infinity(), 1e-40f, 3e38f};
    for (size_t i = 0; i < audio.size(); i += 97) audio[i] = bad[(i / 97) % std::size(bad)];
    ASSERT_EQ(render(write_audio("nan.wav", audio, SF_FORMAT_WAV | SF_FORMAT_FLOAT)).exit_code, 0);
    const auto out = rendered();
    for (const float v : out) ASSERT_TRUE(std::isfinite(v) && std::abs(v) <= 1.0f) << v;
    EXPECT_GT(tactus::test::rms(out), 0.01);
}

// The features a DC offset would move (brightness pulls towards 0 Hz) stay where they are.
TEST_F(BadInput, DcOffsetDoesNotChangeTheVibration) {
    const auto beat = tactus::test::drum_pattern(kRate, 3, 11).audio;
    auto shifted = beat;
    for (float& x : shifted) x = 0.5f * x + 0.4f;
    auto halved = beat;
    for (float& x : halved) x = 0.5f * x;
    const auto frequencies = [&](const fs::path& input) {
        const CliResult r = run("analyze " + input.string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return r.out;
    };
    const std::string plain =
        frequencies(write_audio("plain.wav", halved, SF_FORMAT_WAV | SF_FORMAT_FLOAT));
    const std::string dc =
        frequencies(write_audio("dc.wav", shifted, SF_FORMAT_WAV | SF_FORMAT_FLOAT));
    // Compare the frequency_hz column row by row.
    std::istringstream a(plain), b(dc);
    std::string la, lb;
    std::getline(a, la), std::getline(b, lb);  // the header
    const size_t frequency = tactus::test::csv_column(la, "frequency_hz");
    std::getline(a, la), std::getline(b, lb);  // how they were made
    int rows = 0, different = 0;
    while (std::getline(a, la) && std::getline(b, lb)) {
        const auto column = [&](const std::string& line) {
            return csv_numbers(line).at(frequency);
        };
        ++rows;
        different += std::abs(column(la) - column(lb)) > 0.05 * column(la);
    }
    EXPECT_GT(rows, 500);
    EXPECT_LT(different, rows / 20) << "vibration frequency moved by a DC offset";
}

TEST_F(BadInput, FullScaleSquareWaveStaysUnderTheCeiling) {
    std::vector<float> square(static_cast<size_t>(3 * kRate));
    for (size_t i = 0; i < square.size(); ++i) square[i] = (i / 441) % 2 ? 1.0f : -1.0f;
    ASSERT_EQ(render(write_audio("square.wav", square, SF_FORMAT_WAV | SF_FORMAT_FLOAT)).exit_code,
              0);
    const auto out = rendered();
    EXPECT_LE(tactus::test::peak(out), 1.0);  // the tfd preset's ceiling, 0 dBFS
    EXPECT_GT(tactus::test::rms(out), 0.01);
}

// --- presets and --set: validated before any audio is read ---------------------------------

TEST_F(BadInput, UnknownKeySuggestsTheNearest) {
    const fs::path input = drums("in.wav", 1);
    expect_refused(render(input, "--set envelope.decay=100"),
                   {"--set: unknown key 'envelope.decay' (did you mean 'envelope.decay_ms'?)"});
    const fs::path preset = write_text("p.toml", "[envelope]\ndecai_ms = 3\n");
    expect_refused(
        render(input, "--preset " + preset.string()),
        {"p.toml:2:", "unknown key 'envelope.decai_ms' (did you mean 'envelope.decay_ms'?)"});
}

TEST_F(BadInput, WrongTypeInPreset) {
    const fs::path preset = write_text("p.toml", "[envelope]\ndecay_ms = \"slow\"\n");
    expect_refused(render(drums("in.wav", 1), "--preset " + preset.string()),
                   {"p.toml:2:12: envelope.decay_ms must be a number, 5 to 5000 ms"});
    expect_refused(render(drums("in.wav", 1), "--set envelope.decay_ms=slow"),
                   {"envelope.decay_ms = 'slow' is not a number"});
}

TEST_F(BadInput, OutOfRangeValueStatesTheRangeAndUnit) {
    expect_refused(render(drums("in.wav", 1), "--set envelope.decay_ms=-3"),
                   {"envelope.decay_ms = -3 is out of range: allowed 5 to 5000 ms"});
    const fs::path preset = write_text("p.toml", "[post]\nceiling_db = 3\n");
    expect_refused(render(drums("in.wav", 1), "--preset " + preset.string()),
                   {"p.toml:2:14: post.ceiling_db = 3 is out of range: allowed -40 to 0 dB"});
}

TEST_F(BadInput, MalformedAssignment) {
    for (const char* bad : {"envelope.decay_ms", "=3", "envelope.decay_ms="})
        expect_refused(render(drums("in.wav", 1), std::string("--set '") + bad + "'"),
                       {"expected key=value"});
}

TEST_F(BadInput, TomlSyntaxErrorGivesLineAndColumn) {
    const fs::path preset = write_text("p.toml", "[envelope]\ndecay_ms = = 3\n");
    expect_refused(render(drums("in.wav", 1), "--preset " + preset.string()),
                   {"p.toml:2:", "TOML syntax error"});
}

TEST_F(BadInput, MissingPreset) {
    expect_refused(render(drums("in.wav", 1), "--preset nonesuch"),
                   {"no preset named 'nonesuch' (known: ", "tfd"});
    expect_refused(render(drums("in.wav", 1), "--preset " + (dir_ / "gone.toml").string()),
                   {"preset file '" + (dir_ / "gone.toml").string() + "' not found"});
}

TEST_F(BadInput, ControlCharactersInAKeyStayOnOneLine) {
    expect_refused(render(drums("in.wav", 1), "--set \"$(printf 'a\\nb=1')\""),
                   {"unknown key 'a\\nb'"});
}

// --- outputs -------------------------------------------------------------------------------

TEST_F(BadInput, OutputIsTheInput) {
    const fs::path input = drums("in.wav", 1);
    const auto size = fs::file_size(input);
    const std::string in = input.string();
    expect_refused(run("render " + in + " -o " + in + " --force"),
                   {in + ": output would overwrite the input file"}, dir_ / "none");
    expect_refused(run("analyze " + in + " -o " + in + " --force"),
                   {in + ": output would overwrite the input file"}, dir_ / "none");
    fs::create_symlink(input, dir_ / "link.wav");
    expect_refused(run("render " + in + " -o " + (dir_ / "link.wav").string() + " --force"),
                   {"output would overwrite the input file"}, dir_ / "none");
    EXPECT_EQ(fs::file_size(input), size);
    EXPECT_EQ(tactus::read_mono(input).samples.size(), static_cast<size_t>(kRate));
}

TEST_F(BadInput, ExistingOutputNeedsForce) {
    const fs::path input = drums("in.wav", 1);
    write_text("out.wav", "keep me");
    const CliResult r = render(input);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(out_.string() + ": already exists (use --force to replace it)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(fs::file_size(out_), 7u);
    const fs::path csv = write_text("f.csv", "keep me");
    EXPECT_NE(run("analyze " + input.string() + " -o " + csv.string()).exit_code, 0);
    EXPECT_EQ(fs::file_size(csv), 7u);

    const fs::path txt = write_text("onsets.txt", "keep me");
    EXPECT_NE(run("onsets " + input.string() + " -o " + txt.string()).exit_code, 0);
    EXPECT_EQ(fs::file_size(txt), 7u);

    ASSERT_EQ(render(input, "--force").exit_code, 0);
    tactus::test::expect_input_plus_tail(static_cast<int64_t>(rendered().size()),
                                         static_cast<int64_t>(kRate), kRate);
    ASSERT_EQ(run("analyze " + input.string() + " -o " + csv.string() + " --force").exit_code, 0);
    EXPECT_GT(fs::file_size(csv), 1000u);
    expect_no_temporaries();
}

TEST_F(BadInput, OutputDirectoryMissing) {
    const fs::path out = dir_ / "nowhere" / "out.wav";
    expect_refused(run("render " + drums("in.wav", 1).string() + " -o " + out.string()),
                   {out.string() + ": cannot write: directory '", "' does not exist"}, out);
}

TEST_F(BadInput, OutputIsADirectory) {
    fs::create_directory(dir_ / "sub");
    expect_refused(run("render " + drums("in.wav", 1).string() + " -o " + (dir_ / "sub").string() +
                       " --force"),
                   {"sub: is a directory"}, dir_ / "none");
}

TEST_F(BadInput, UnwritableDirectory) {
    const fs::path input = drums("in.wav", 1);
    const fs::path locked = dir_ / "locked";
    fs::create_directory(locked);
    fs::permissions(dir_, fs::perms::all);
    fs::permissions(input, fs::perms::all);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                fs::perms::group_exec | fs::perms::others_read |
                                fs::perms::others_exec);
    for (const char* command : {"render", "analyze"}) {
        const fs::path out = locked / (std::string(command) == "render" ? "out.wav" : "out.csv");
        const CliResult r =
            run_unprivileged(std::string(command) + " " + input.string() + " -o " + out.string());
        EXPECT_NE(r.exit_code, 0) << command;
        EXPECT_NE(r.err.find(out.string() + ": cannot write"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("Permission denied"), std::string::npos) << r.err;
        EXPECT_TRUE(fs::is_empty(locked));
    }
}

TEST_F(BadInput, StdoutOnAFullDevice) {
    const fs::path input = drums("in.wav", 3);
    for (const char* command : {"analyze", "onsets"}) {
        const CliResult r = run(std::string(command) + " " + input.string() + " >/dev/full");
        EXPECT_NE(r.exit_code, 0) << command;
        EXPECT_EQ(r.err, "tactus: error: stdout: write failed: No space left on device\n")
            << command;
    }
}

// A 64 KiB tmpfs (needs root and mount permission; skipped otherwise).
class FullDisk : public BadInput {
  protected:
    void SetUp() override {
        BadInput::SetUp();
        small_ = dir_ / "small";
        fs::create_directory(small_);
        if (geteuid() != 0 || mount("tmpfs", small_.c_str(), "tmpfs", 0, "size=64k") != 0)
            GTEST_SKIP() << "cannot mount a small tmpfs here";
        mounted_ = true;
    }
    void TearDown() override {
        if (mounted_) umount(small_.c_str());
        BadInput::TearDown();
    }
    fs::path small_;
    bool mounted_ = false;
};

TEST_F(FullDisk, RenderAndAnalyzeReportNoSpaceAndLeaveNothing) {
    const fs::path input = drums("in.wav", 10);
    const fs::path wav = small_ / "out.wav", csv = small_ / "out.csv";
    const CliResult r = run("render " + input.string() + " -o " + wav.string());
    expect_refused(r, {wav.string(), "No space left on device"}, wav);
    const CliResult a = run("analyze " + input.string() + " -o " + csv.string());
    expect_refused(a, {csv.string(), "No space left on device"}, csv);
    EXPECT_TRUE(fs::is_empty(small_));
}

// Ctrl-C or kill in the middle of a render: the hidden temporary is removed, the target never
// appears, and the process still dies of the signal.
class Interrupted : public BadInput {
  protected:
    // Starts a render of a long file, waits until its temporary exists, sends `signal_number`.
    int render_and_signal(int signal_number) {
        const fs::path input = drums("long.wav", 300);
        const pid_t pid = fork();
        if (pid == 0) {
            const int null = open("/dev/null", O_WRONLY);
            dup2(null, 2);
            execl(TACTUS_CLI, TACTUS_CLI, "render", input.c_str(), "-o", out_.c_str(), nullptr);
            _exit(127);
        }
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (!has_temporary() && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        EXPECT_TRUE(has_temporary());
        std::this_thread::sleep_for(std::chrono::milliseconds(50));  // mid-write
        kill(pid, signal_number);
        int status = 0;
        waitpid(pid, &status, 0);
        EXPECT_TRUE(WIFSIGNALED(status));
        return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    }
    bool has_temporary() const {
        for (const auto& entry : fs::directory_iterator(dir_))
            if (entry.path().filename().string().starts_with(".out.wav.tmp-")) return true;
        return false;
    }
};

TEST_F(Interrupted, SigintAndSigtermLeaveNoFile) {
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
        EXPECT_EQ(render_and_signal(signal_number), signal_number);
        EXPECT_FALSE(fs::exists(out_));
        EXPECT_FALSE(has_temporary()) << strsignal(signal_number);
    }
}

TEST_F(Interrupted, SigkillLeavesOnlyTheHiddenTemporary) {
    EXPECT_EQ(render_and_signal(SIGKILL), SIGKILL);
    EXPECT_FALSE(fs::exists(out_));
    EXPECT_TRUE(has_temporary());
}

}  // namespace
