// The command line as a haptic designer tries it: formats named by the output's extension and
// sample formats, pipes both ways, devices, pipes and symlinks written through, short sounds
// with their whole pulse, --version, --quiet, "did you mean", names typed loosely, the actuator
// and preset listings, and how an output was made carried in it (and read back by meter).
#include <gtest/gtest.h>
#include <sndfile.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/sounds.hpp"
#include "tactus/io/audio_reader.hpp"

namespace {

namespace fs = std::filesystem;
using tactus::test::Cli;
using tactus::test::info_of;
using Result = tactus::test::CliResult;

using tactus::test::kAmen;
const std::string kTick = "/usr/share/sonic-pi/samples/elec_tick.flac";  // 19 ms
const std::string kProgram = TACTUS_CLI;

std::string comment_of(const fs::path& path, int which = SF_STR_COMMENT) {
    SF_INFO info{};
    SNDFILE* f = sf_open(path.c_str(), SFM_READ, &info);
    if (!f) return {};
    const char* text = sf_get_string(f, which);
    std::string s = text ? text : "";
    sf_close(f);
    return s;
}

float peak(const std::vector<float>& x, size_t from = 0, size_t to = SIZE_MAX) {
    float p = 0;
    for (size_t i = from; i < std::min(to, x.size()); ++i) p = std::max(p, std::abs(x[i]));
    return p;
}

TEST_F(Cli, RenderWritesTheFormatItsOutputNames) {
    struct Case {
        const char* name;
        const char* options;
        int format;
    };
    for (const Case& c : {Case{"v.wav", "", SF_FORMAT_WAV | SF_FORMAT_FLOAT},
                          Case{"v16.wav", "--sample-format 16", SF_FORMAT_WAV | SF_FORMAT_PCM_16},
                          Case{"v24.wav", "--sample-format 24", SF_FORMAT_WAV | SF_FORMAT_PCM_24},
                          Case{"v.flac", "", SF_FORMAT_FLAC | SF_FORMAT_PCM_24},
                          Case{"v16.flac", "--sample-format 16", SF_FORMAT_FLAC | SF_FORMAT_PCM_16},
                          Case{"v.ogg", "", SF_FORMAT_OGG | SF_FORMAT_VORBIS},
                          Case{"v.mp3", "", SF_FORMAT_MPEG | SF_FORMAT_MPEG_LAYER_III}}) {
        const fs::path out = dir_ / c.name;
        const Result r = run("render " + kTick + " -o " + out.string() + " " + c.options);
        ASSERT_EQ(r.exit_code, 0) << c.name << ": " << r.err;
        EXPECT_EQ(info_of(out).format, c.format) << c.name;
        EXPECT_GT(peak(tactus::read_mono(out).samples), 0.05f) << c.name;
    }
    // Containers libsndfile cannot write, and sample formats a container cannot hold, are
    // refused before anything is written.
    for (const auto& [name, options, message] :
         {std::tuple{"v.txt", "", "v.txt: cannot write sound as '.txt' (name it .wav, .flac"},
          std::tuple{"v.mp4", "", "cannot write sound as '.mp4'"},
          std::tuple{"f.flac", "--sample-format float", "f.flac: .flac holds 16- or 24-bit"},
          std::tuple{"c.ogg", "--sample-format 16", "c.ogg: .ogg is compressed"}}) {
        const Result r = run("render " + kTick + " -o " + (dir_ / name).string() + " " + options);
        EXPECT_NE(r.exit_code, 0) << name;
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir_ / name)) << name;
    }
    expect_no_temporaries();
}

// `-o -` writes WAV to stdout (no file named "-"), `-` reads any format from stdin: the two piped
// give what a render to a file gives.
TEST_F(Cli, RenderStreamsWavThroughPipesBothWays) {
    const fs::path file = dir_ / "file.wav", piped = dir_ / "piped.wav";
    ASSERT_EQ(run("render " + kAmen + " -o " + file.string()).exit_code, 0);
    const Result r = run("render - -o - 2>/dev/null < " + kAmen + " | " + kProgram +
                             " render - -o - -q | cat > " + piped.string(),
                         "cd " + dir_.string() + " && ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "-"));
    // Rendering twice renders the vibration of the vibration: compare one pass instead.
    const fs::path once = dir_ / "once.wav";
    ASSERT_EQ(run("render - -o - < " + kAmen + " > " + once.string()).exit_code, 0);
    const auto a = tactus::read_mono(file).samples, b = tactus::read_mono(once).samples;
    ASSERT_EQ(a.size(), b.size());
    EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin()));
    EXPECT_EQ(info_of(once).format, SF_FORMAT_WAV | SF_FORMAT_FLOAT);
    EXPECT_GT(info_of(piped).frames, info_of(once).frames);  // its own tail again
    // meter reads stdin too.
    const Result m = run("meter - < " + file.string());
    ASSERT_EQ(m.exit_code, 0) << m.err;
    EXPECT_NE(m.out.find("P        vibration"), std::string::npos) << m.out;
}

// A device, a pipe or a symlink's target is written through, never replaced.
TEST_F(Cli, DevicesPipesAndSymlinksAreWrittenThrough) {
    const Result r = run("render " + kTick + " -o /dev/stdout --force");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.substr(0, 4), "RIFF");
    EXPECT_TRUE(fs::is_symlink("/dev/stdout"));

    const fs::path target = dir_ / "target.wav", link = dir_ / "link.wav";
    std::ofstream(target) << "old";
    fs::create_symlink(target, link);
    ASSERT_EQ(run("render " + kTick + " -o " + link.string() + " --force").exit_code, 0);
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(fs::read_symlink(link), target);
    EXPECT_EQ(info_of(target).format, SF_FORMAT_WAV | SF_FORMAT_FLOAT);

    const fs::path fifo = dir_ / "fifo", got = dir_ / "got.wav";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const Result f = run("render -q " + kTick + " -o " + fifo.string() + " & cat " + fifo.string() +
                         " > " + got.string() + "; wait");
    ASSERT_EQ(f.exit_code, 0) << f.err;
    EXPECT_TRUE(fs::is_fifo(fifo));
    EXPECT_EQ(info_of(got).format, SF_FORMAT_WAV | SF_FORMAT_FLOAT);
    expect_no_temporaries();
}

// A 19 ms tick and a 2 ms click keep their whole pulse: the output runs on until the vibration
// has died away (the 150 ms decay to -60 dB), and ends in silence.
TEST_F(Cli, ShortSoundsKeepTheVibrationsTail) {
    const fs::path click = dir_ / "click.wav";
    std::vector<float> burst(88);  // 2 ms at 44.1 kHz
    for (size_t i = 0; i < burst.size(); ++i) burst[i] = (i / 22) % 2 ? -0.8f : 0.8f;
    tactus::test::write_sound_file(click, burst, 44100);
    for (const std::string& input : {kTick, click.string()}) {
        const fs::path out = dir_ / "out.wav";
        ASSERT_EQ(run("render " + input + " -o " + out.string() + " --force").exit_code, 0);
        const auto v = tactus::read_mono(out).samples;
        const size_t input_frames = static_cast<size_t>(info_of(input).frames);
        ASSERT_GT(v.size(), input_frames + static_cast<size_t>(0.15 * 44100)) << input;
        const float top = peak(v);
        EXPECT_GT(top, 0.05f) << input;
        // The pulse is still sounding where the input ends, and has decayed by -60 dB before
        // the output ends.
        EXPECT_GT(peak(v, input_frames, input_frames + 441), 0.1f * top) << input;
        EXPECT_LT(peak(v, v.size() - 441), 1e-3f * top) << input;
    }
}

TEST_F(Cli, VersionSuggestionsAndLooselyTypedNames) {
    const Result v = run("--version");
    EXPECT_EQ(v.exit_code, 0);
    EXPECT_EQ(v.out, "tactus " TACTUS_VERSION "\n");
    const Result typo = run("rendr " + kTick);
    EXPECT_EQ(typo.exit_code, 1);
    EXPECT_NE(typo.err.find("unknown command 'rendr' (did you mean 'render'?"), std::string::npos)
        << typo.err;
    const Result preset =
        run("render " + kTick + " -o " + (dir_ / "x.wav").string() + " -p four_chanel");
    EXPECT_NE(preset.exit_code, 0);
    EXPECT_NE(preset.err.find("no preset named 'four_chanel' (did you mean 'four-channel'?"),
              std::string::npos)
        << preset.err;
    const Result actuator =
        run("render " + kTick + " -o " + (dir_ / "x.wav").string() + " -a lra-157");
    EXPECT_NE(actuator.err.find("did you mean 'lra-175'?"), std::string::npos) << actuator.err;
    // Case and '_' for '-' do not matter.
    const Result loose =
        run("render " + kTick + " -o " + (dir_ / "y.wav").string() + " -p Four_Channel -a LRA_175");
    EXPECT_EQ(loose.exit_code, 0) << loose.err;
    EXPECT_NE(comment_of(dir_ / "y.wav").find("actuator=lra-175"), std::string::npos);
}

TEST_F(Cli, ActuatorsListedAndPresetValuesShown) {
    const Result list = run("actuators");
    ASSERT_EQ(list.exit_code, 0) << list.err;
    for (const char* name : {"voice-coil", "lra-175", "erm"})
        EXPECT_NE(list.out.find(name), std::string::npos) << name;
    const Result one = run("actuators LRA-175");
    ASSERT_EQ(one.exit_code, 0) << one.err;
    EXPECT_NE(one.out.find("175 Hz Q 10 (band-pass)"), std::string::npos) << one.out;
    EXPECT_NE(one.out.find("0.7 (-3.1 dBFS)"), std::string::npos) << one.out;
    const Result show = run("presets --show four-channel --set envelope.decay_ms=90");
    ASSERT_EQ(show.exit_code, 0) << show.err;
    EXPECT_NE(show.out.find("* envelope.decay_ms"), std::string::npos) << show.out;
    EXPECT_NE(show.out.find("  analysis.hop_ms"), std::string::npos) << show.out;  // a default
}

// Expected warnings (an actuator that cannot follow the preset) are silenced by --quiet, before
// or after the command; errors are not.
TEST_F(Cli, QuietSilencesWarningsAndSummariesNotErrors) {
    const std::string render =
        "render " + kTick + " -a lra-175 --force -o " + (dir_ / "q.wav").string();
    EXPECT_NE(run(render).err.find("warning"), std::string::npos);
    for (const std::string& command : {"-q " + render, render + " --quiet"}) {
        const Result r = run(command);
        EXPECT_EQ(r.exit_code, 0);
        EXPECT_EQ(r.err, "") << command;
    }
    EXPECT_NE(run("-q render " + kTick + " -o " + (dir_ / "q.txt").string()).err.find("error"),
              std::string::npos);
}

// A render says how it was made in its INFO chunk; meter reads the actuator from it: an LRA
// render is metered through the LRA, as if --actuator had named it.
TEST_F(Cli, RenderCarriesHowItWasMadeAndMeterReadsTheActuator) {
    const fs::path lra = dir_ / "lra.wav";
    const std::string keep = " --set mapping.frequency.out_min=160 mapping.frequency.out_max=220";
    ASSERT_EQ(run("render " + kAmen + " -o " + lra.string() + " -a lra-175" + keep).exit_code, 0);
    EXPECT_EQ(comment_of(lra, SF_STR_SOFTWARE).rfind("tactus " TACTUS_VERSION, 0), 0u);
    EXPECT_EQ(comment_of(lra), "tactus=" TACTUS_VERSION
                               "; source=loop_amen_full.flac; preset=music; "
                               "set=mapping.frequency.out_min=160 mapping.frequency.out_max=220; "
                               "actuator=lra-175");
    const Result read = run("meter " + lra.string());
    const Result named = run("meter " + lra.string() + " -a lra-175");
    const Result voice_coil = run("meter " + lra.string() + " -a voice-coil");
    ASSERT_EQ(read.exit_code, 0) << read.err;
    EXPECT_NE(read.err.find("rendered for lra-175"), std::string::npos) << read.err;
    EXPECT_EQ(read.out, named.out);
    EXPECT_NE(read.out, voice_coil.out);
    std::cout << read.out << voice_coil.out;
}

}  // namespace

namespace {

// Every command takes folders and many files the same way: with -O the input folder's tree is
// mirrored, and --skip-existing resumes a batch without touching what exists.
TEST_F(Cli, EveryCommandBatchesMirroringFoldersAndSkippingExistingOutputs) {
    const fs::path tree = dir_ / "sounds", out = dir_ / "out";
    fs::create_directories(tree / "kicks");
    fs::create_directories(tree / "snares" / "soft");
    fs::copy_file("/usr/share/sonic-pi/samples/bd_808.flac", tree / "kicks" / "bd_808.flac");
    fs::copy_file("/usr/share/sonic-pi/samples/bd_zome.flac", tree / "kicks" / "bd_zome.flac");
    fs::copy_file("/usr/share/sonic-pi/samples/sn_dolf.flac", tree / "snares" / "soft" / "sn.flac");
    const std::vector<std::string> stems = {"kicks/bd_808", "kicks/bd_zome", "snares/soft/sn"};
    for (const auto& [command, suffix] :
         {std::pair{"render", ".vibration.wav"}, std::pair{"analyze", ".features.csv"},
          std::pair{"onsets", ".onsets.txt"}, std::pair{"export", ".ahap"},
          std::pair{"report", ".report.html"}}) {
        const Result r = run(std::string(command) + " " + tree.string() + " -O " + out.string());
        ASSERT_EQ(r.exit_code, 0) << command << ": " << r.err;
        for (const auto& stem : stems) EXPECT_TRUE(fs::exists(out / (stem + suffix))) << stem;
    }
    for (const char* format : {".haptic", ".android.json", ".ogg"})  // export: every format
        for (const auto& stem : stems) EXPECT_TRUE(fs::exists(out / (stem + format))) << stem;
    // meter takes the rendered tree.
    const fs::path rendered = dir_ / "rendered";
    ASSERT_EQ(run("render " + tree.string() + " -O " + rendered.string()).exit_code, 0);
    const Result m = run("meter " + rendered.string() + " -O " + (dir_ / "metered").string());
    ASSERT_EQ(m.exit_code, 0) << m.err;
    for (const auto& stem : stems)
        EXPECT_TRUE(fs::exists(dir_ / "metered" / (stem + ".vibration.meter.csv"))) << stem;
    EXPECT_EQ(std::count(m.out.begin(), m.out.end(), '\n'), 3 * 7) << m.out;  // 3 summaries

    // Again: existing outputs are refused without --force, left as they are with --skip-existing.
    const fs::path kept = out / "kicks" / "bd_808.onsets.txt";
    std::ofstream(kept) << "kept";
    fs::remove(out / "snares" / "soft" / "sn.onsets.txt");
    const Result again = run("onsets " + tree.string() + " -O " + out.string());
    EXPECT_NE(again.exit_code, 0);
    EXPECT_NE(again.err.find("already exists"), std::string::npos) << again.err;
    const Result resumed =
        run("onsets " + tree.string() + " -O " + out.string() + " --skip-existing");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_NE(resumed.err.find("2 output(s) exist: skipped"), std::string::npos) << resumed.err;
    std::ifstream k(kept);
    std::string text((std::istreambuf_iterator<char>(k)), {});
    EXPECT_EQ(text, "kept");
    EXPECT_TRUE(fs::exists(out / "snares" / "soft" / "sn.onsets.txt"));
    // Several files without -O are refused for every command.
    for (const char* command : {"render", "analyze", "onsets", "meter", "export", "report"}) {
        const Result many = run(std::string(command) + " " + kTick + " " + kTick + " -o x");
        EXPECT_NE(many.exit_code, 0) << command;
        EXPECT_NE(many.err.find("use -O DIR"), std::string::npos) << command << many.err;
    }
    expect_no_temporaries();
}

}  // namespace

namespace {

// Every command that takes several inputs says a batch's mistakes in the same words, before any
// audio is read: one batch path for all of them.
TEST_F(Cli, EveryCommandSaysBatchMistakesInTheSameWords) {
    const std::string both = "-o names one output but 2 inputs were given; use -O DIR";
    const std::string either = "give either -o FILE (one input) or -O DIR, not both";
    std::ofstream(dir_ / "file") << "not a folder";
    const fs::path blocked = dir_ / "file" / "out";
    for (const char* command :
         {"render", "analyze", "onsets", "meter", "simulate", "export", "report"}) {
        const std::string c = command;
        const Result many = run(c + " " + kTick + " " + kTick + " -o x.ahap");
        EXPECT_NE(many.exit_code, 0) << c;
        EXPECT_NE(many.err.find("tactus: error: " + both), std::string::npos) << c << many.err;
        const Result two = run(c + " " + kTick + " -o x.ahap -O " + dir_.string());
        EXPECT_NE(two.exit_code, 0) << c;
        EXPECT_NE(two.err.find("tactus: error: " + either), std::string::npos) << c << two.err;
        const Result folder = run(c + " " + kTick + " -O " + blocked.string());
        EXPECT_NE(folder.exit_code, 0) << c;
        EXPECT_NE(folder.err.find(": cannot create the output directory: "), std::string::npos)
            << c << folder.err;
    }
    // The commands that write a file, never stdout, say so in the same words.
    for (const char* command : {"render", "simulate", "export"}) {
        const Result none = run(std::string(command) + " " + kTick);
        EXPECT_NE(none.exit_code, 0) << command;
        EXPECT_NE(none.err.find(std::string("tactus: error: ") + command +
                                ": give either -o FILE (one input) or -O DIR"),
                  std::string::npos)
            << command << none.err;
    }
    expect_no_temporaries();
}

}  // namespace
