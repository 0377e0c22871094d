// tactus~ in a real Pd: `pd -nogui -batch` plays a sound file through the external
// (tests/pd/render_through.pd) and writes what it made; each output is compared with `tactus
// render` of the same file, or with the library's Engine driven the same way.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/sound_file.hpp"
#include "tactus/core/units.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/preset.hpp"

namespace tactus::test {
namespace {

constexpr double kRateHz = 44100;
constexpr int kPdBlock = 64;  // Pd's default block: the ticks messages arrive between
constexpr float kTolerance = 1e-5f;

// A file's channels, each as a vector.
std::vector<std::vector<float>> read_channels(const std::filesystem::path& path) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    if (!file) return {};
    std::vector<float> interleaved(static_cast<size_t>(info.frames * info.channels));
    sf_readf_float(file, interleaved.data(), info.frames);
    sf_close(file);
    std::vector<std::vector<float>> channels(static_cast<size_t>(info.channels));
    for (size_t i = 0; i < interleaved.size(); ++i)
        channels[i % channels.size()].push_back(interleaved[i]);
    return channels;
}

// Under ThreadSanitizer the instrumented tactus~ needs the TSan runtime inside pd, which is not
// instrumented: ctest's environment names it (TACTUS_HOST_PRELOAD, tests/CMakeLists.txt), and it
// is preloaded into pd alone (a shell does not run with it: sh and bash crash).
std::string host_preload() {
    const char* runtime = std::getenv("TACTUS_HOST_PRELOAD");
    return runtime && *runtime ? std::string("LD_PRELOAD=") + runtime + " " : std::string();
}

float largest_difference(const std::vector<float>& a, const std::vector<float>& b) {
    EXPECT_EQ(a.size(), b.size());
    float largest = 0;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        largest = std::max(largest, std::abs(a[i] - b[i]));
    return largest;
}

class PdExternal : public Cli {
  protected:
    void SetUp() override {
        Cli::SetUp();
        // The Amen break, mono, as 32-bit float: Pd and libsndfile read the same samples.
        AudioReader reader{std::filesystem::path(kAmen)};
        std::vector<std::vector<float>> channels(static_cast<size_t>(reader.channels()),
                                                 std::vector<float>(4096));
        std::vector<float*> pointers;
        for (auto& c : channels) pointers.push_back(c.data());
        std::vector<float> mono;
        while (const int n = reader.read(pointers.data(), 4096))
            for (size_t i = 0; i < static_cast<size_t>(n); ++i) {
                float sum = 0;
                for (const auto& c : channels) sum += c[i];
                mono.push_back(sum / static_cast<float>(channels.size()));
            }
        input_ = mono;
        ASSERT_NO_FATAL_FAILURE(write_sound_file(dir_ / "in.wav", input_, kRateHz));
    }

    // Runs the test patch with these messages to tactus~ before the start, and `score`, lines
    // of timed messages after it ("MS tactus-msg KEY VALUE;", each MS after the one before);
    // returns the three outputs (actuator 0, actuator 1, thru) and keeps Pd's stderr.
    std::vector<std::vector<float>> run_pd(const std::vector<std::string>& messages,
                                           const std::string& score = "",
                                           const std::string& prefix = "") {
        const std::filesystem::path guard_dir =
            std::filesystem::path(TACTUS_PD_GUARD).parent_path();
        std::string command =
            (prefix.empty() ? host_preload() : prefix) + TACTUS_PD + " -nogui -batch -noaudio -r " +
            std::to_string(static_cast<int>(kRateHz)) + " -path " + TACTUS_PD_DIR + "/.. -path " +
            guard_dir.string() + " -open " + TACTUS_SOURCE_DIR + "/tests/pd/render_through.pd";
        for (const std::string& m : messages) command += " -send \"tactus-msg " + m + "\"";
        if (!score.empty()) {
            std::ofstream(dir_ / "score.txt") << score;
            command += " -send \"tactus-score symbol " + (dir_ / "score.txt").string() + "\"";
        }
        command += " -send \"tactus-out symbol " + (dir_ / "pd.wav").string() + "\"";
        command += " -send \"tactus-in symbol " + (dir_ / "in.wav").string() + "\"";
        command += " 2>" + (dir_ / "pd.txt").string();
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
        std::ifstream log(dir_ / "pd.txt");
        pd_log_.assign(std::istreambuf_iterator<char>(log), {});
        return read_channels(dir_ / "pd.wav");
    }

    std::vector<float> render(const std::string& options = "") {
        const CliResult r = run("render " + (dir_ / "in.wav").string() + " -o " +
                                (dir_ / "ref.wav").string() + " --force " + options);
        EXPECT_EQ(r.exit_code, 0) << r.err;
        auto channels = read_channels(dir_ / "ref.wav");
        if (channels.empty()) return {};
        // The command rings the vibration's tail out past the input; Pd plays the input's length.
        EXPECT_GE(channels[0].size(), input_.size());
        channels[0].resize(std::min(channels[0].size(), input_.size()));
        return channels[0];
    }

    // A two-output layout beside the patch (the test's folder), the outputs on these routes.
    void write_layout(const std::string& name, const std::string& first,
                      const std::string& second) {
        std::ofstream(dir_ / name) << "[[output]]\nroute = \"" << first
                                   << "\"\n[[output]]\nroute = \"" << second << "\"\n";
    }
    // Both outputs of `tactus render --layout`, the input's length.
    std::vector<std::vector<float>> render_layout(const std::string& layout) {
        const CliResult r =
            run("render " + (dir_ / "in.wav").string() + " -o " + (dir_ / "ref.wav").string() +
                " --force --layout " + (dir_ / layout).string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        auto channels = read_channels(dir_ / "ref.wav");
        for (auto& c : channels) c.resize(std::min(c.size(), input_.size()));
        return channels;
    }

    static constexpr const char* kAmen = "/usr/share/sonic-pi/samples/loop_amen.flac";
    std::vector<float> input_;
    std::string pd_log_;
};

TEST_F(PdExternal, DefaultsEqualRender) {
    const auto pd = run_pd({});
    ASSERT_EQ(pd.size(), 3u) << pd_log_;
    const auto reference = render();
    const float difference = largest_difference(pd[0], reference);
    std::printf("tactus~ against tactus render, largest difference: %g\n", difference);
    EXPECT_LE(difference, kTolerance);
    EXPECT_EQ(largest_difference(pd[1], pd[0]), 0.0f);  // every outlet plays the one signal
    EXPECT_GT(*std::max_element(reference.begin(), reference.end()), 0.05f);
}

TEST_F(PdExternal, PresetAndParameterMessagesEqualRenderWithThem) {
    const auto pd =
        run_pd({"preset four-channel", "envelope.decay_ms 80", "mapping.frequency.curve lin"});
    ASSERT_EQ(pd.size(), 3u) << pd_log_;
    const auto reference =
        render("--preset four-channel --set envelope.decay_ms=80 mapping.frequency.curve=lin");
    EXPECT_LE(largest_difference(pd[0], reference), kTolerance);
    EXPECT_GT(largest_difference(pd[0], render()), 0.01f);  // the messages changed something
}

TEST_F(PdExternal, ThruIsTheInputDelayedByTheLatency) {
    const auto pd = run_pd({});
    ASSERT_EQ(pd.size(), 3u) << pd_log_;
    Engine engine;
    engine.prepare(kRateHz, kPdBlock);
    const auto latency = static_cast<size_t>(engine.latency());
    ASSERT_GT(latency, 0u);
    for (size_t i = 0; i < input_.size(); ++i)
        ASSERT_EQ(pd[2][i], i < latency ? 0.0f : input_[i - latency]) << "sample " << i;
}

// post.lookahead_ms is structural: mid-file, it moves the engine's latency without a new
// prepare, and the thru outlet follows it (the input delayed by the latency the engine reports
// after each block), so the music stays aligned with the vibration.
TEST_F(PdExternal, ThruFollowsTheLatencyWhenTheLookAheadChanges) {
    constexpr int kBlock = 400;  // the change is due inside it (Pd delivers it before)
    const double at_ms = (kBlock + 0.5) * kPdBlock / kRateHz * 1000;
    const auto pd = run_pd({}, fmt::format("{:.6f} tactus-msg post.lookahead_ms 20;", at_ms));
    ASSERT_EQ(pd.size(), 3u) << pd_log_;

    Engine engine;
    engine.prepare(kRateHz, kPdBlock);
    const int before = engine.latency();
    std::vector<float> vibration(input_.size()), thru(input_.size());
    for (size_t done = 0; done < input_.size(); done += kPdBlock) {
        if (done == static_cast<size_t>(kBlock) * kPdBlock) engine.set(P::post_lookahead_ms, 20);
        const int n = static_cast<int>(std::min<size_t>(kPdBlock, input_.size() - done));
        engine.process(input_.data() + done, vibration.data() + done, n);
        const auto latency = static_cast<size_t>(engine.latency());
        for (size_t i = done; i < done + static_cast<size_t>(n); ++i)
            thru[i] = i < latency ? 0.0f : input_[i - latency];
    }
    const int after = engine.latency();
    ASSERT_GT(after - before, ms_to_samples(19, kRateHz)) << "the look-ahead moved the latency";
    const auto split = static_cast<ptrdiff_t>(kBlock) * kPdBlock;
    EXPECT_TRUE(std::equal(pd[0].begin(), pd[0].begin() + split, vibration.begin()));
    for (size_t i = 0; i < input_.size(); ++i)
        ASSERT_EQ(pd[2][i], thru[i]) << "sample " << i << ", latency " << before << " -> " << after;
}

// `reset` mid-file starts the object again from silence: the vibration is the engine's with
// Engine::reset at the block Pd delivers it before, and the thru outlet's delay line is
// cleared too (the music before the reset does not come out after it).
TEST_F(PdExternal, ResetClearsTheVibrationAndTheThruDelayLine) {
    constexpr int kBlock = 400;  // the reset is due inside it (Pd delivers it before)
    const double at_ms = (kBlock + 0.5) * kPdBlock / kRateHz * 1000;
    const auto pd = run_pd({}, fmt::format("{:.6f} tactus-msg reset;", at_ms));
    ASSERT_EQ(pd.size(), 3u) << pd_log_;

    Engine engine;
    engine.prepare(kRateHz, kPdBlock);
    const auto latency = static_cast<size_t>(engine.latency());
    const size_t split = static_cast<size_t>(kBlock) * kPdBlock;
    ASSERT_GT(*std::max_element(input_.begin() + static_cast<ptrdiff_t>(split - latency),
                                input_.begin() + static_cast<ptrdiff_t>(split)),
              0.01f)
        << "music in the delay line when the reset comes";
    std::vector<float> vibration(input_.size());
    for (size_t done = 0; done < input_.size(); done += kPdBlock) {
        if (done == split) engine.reset();
        const int n = static_cast<int>(std::min<size_t>(kPdBlock, input_.size() - done));
        engine.process(input_.data() + done, vibration.data() + done, n);
    }
    EXPECT_LE(largest_difference(pd[0], vibration), kTolerance);
    for (size_t i = 0; i < input_.size(); ++i) {
        const bool silent = i < latency || (i >= split && i < split + latency);
        ASSERT_EQ(pd[2][i], silent ? 0.0f : input_[i - latency]) << "sample " << i;
    }
}

// A message in the middle of the file acts as Engine::set() at the block Pd delivers it before:
// from there the output is the engine's with the change, before it the defaults' output.
TEST_F(PdExternal, AMessageMidFileActsAsTheEnginesSetFromItsBlock) {
    // Due inside block k (half a block in), Pd delivers it before that block; k is taken just
    // before the loudest output, where a change of the limiter's drive shows at once.
    const auto unchanged = render();
    const auto loudest = std::max_element(unchanged.begin(), unchanged.end(), [](float a, float b) {
        return std::abs(a) < std::abs(b);
    });
    const int block = static_cast<int>((loudest - unchanged.begin()) / kPdBlock) - 1;
    const double at_ms = (block + 0.5) * kPdBlock / kRateHz * 1000;
    const auto pd = run_pd({}, fmt::format("{:.6f} tactus-msg post.drive_db 3;", at_ms));
    ASSERT_EQ(pd.size(), 3u) << pd_log_;

    Engine engine;
    engine.prepare(kRateHz, kPdBlock);
    std::vector<float> reference(input_.size());
    for (size_t done = 0; done < input_.size(); done += kPdBlock) {
        if (done == static_cast<size_t>(block) * kPdBlock) engine.set(P::post_drive_db, 3);
        const int n = static_cast<int>(std::min<size_t>(kPdBlock, input_.size() - done));
        engine.process(input_.data() + done, reference.data() + done, n);
    }
    EXPECT_LE(largest_difference(pd[0], reference), kTolerance);
    const auto split = static_cast<ptrdiff_t>(block) * kPdBlock;
    EXPECT_TRUE(std::equal(pd[0].begin(), pd[0].begin() + split, unchanged.begin()));
    EXPECT_FALSE(std::equal(pd[0].begin() + split, pd[0].end(), unchanged.begin() + split));
}

// The onset outlet sends `PART STRENGTH_DB` for every onset `tactus onsets` prints, with its part
// and strength ("onset_s decided_s strength_db part").
TEST_F(PdExternal, TheOnsetOutletSendsEveryOnsetOfTactusOnsetsWithItsPart) {
    run_pd({});
    const CliResult onsets = run("onsets " + (dir_ / "in.wav").string());
    ASSERT_EQ(onsets.exit_code, 0) << onsets.err;
    struct Onset {
        std::string part;
        double strength_db;
    };
    std::vector<Onset> expected, sent;
    std::istringstream printed(onsets.out), log(pd_log_);
    for (std::string line; std::getline(printed, line);) {
        std::istringstream fields(line);
        double onset_s = 0, decided_s = 0;
        Onset o;
        fields >> onset_s >> decided_s >> o.strength_db >> o.part;
        expected.push_back(o);
    }
    for (std::string line; std::getline(log, line);) {
        if (!line.starts_with("tactus-onset: ")) continue;
        std::istringstream fields(line.substr(14));  // [print]: "tactus-onset: kick -12.5"
        Onset o;
        fields >> o.part >> o.strength_db;
        sent.push_back(o);
    }
    EXPECT_GT(expected.size(), 5u);
    ASSERT_EQ(sent.size(), expected.size()) << pd_log_;
    std::set<std::string> parts;
    for (size_t i = 0; i < sent.size(); ++i) {
        EXPECT_EQ(sent[i].part, expected[i].part) << "onset " << i;
        EXPECT_NEAR(sent[i].strength_db, expected[i].strength_db, 0.006) << "onset " << i;
        parts.insert(sent[i].part);
    }
    EXPECT_GE(parts.size(), 2u) << "the Amen break's kick and snare at least";
}

// `route OUTLET ROUTE` and `layout FILE` play as `tactus render --layout`
// with those routes; a bad route says why and changes nothing.
TEST_F(PdExternal, RoutesAndLayoutsPlayAsRenderWithThem) {
    write_layout("kick-band.toml", "all", "band:20-120");
    const auto reference = render_layout("kick-band.toml");
    const auto routed = run_pd({"route 1 band:20-120", "route 0 kicks"});
    ASSERT_EQ(routed.size(), 3u) << pd_log_;
    EXPECT_NE(pd_log_.find("route 'kicks'"), std::string::npos) << pd_log_;
    for (size_t k = 0; k < 2; ++k)
        EXPECT_LE(largest_difference(routed[k], reference[k]), kTolerance);
    EXPECT_GT(largest_difference(routed[1], routed[0]), 0.01f) << "the outlets play apart";

    write_layout("snare-left.toml", "snare", "channel:1");
    const auto laid_out = run_pd({"layout " + (dir_ / "snare-left.toml").string()});
    ASSERT_EQ(laid_out.size(), 3u) << pd_log_;
    const auto expected = render_layout("snare-left.toml");
    for (size_t k = 0; k < 2; ++k)
        EXPECT_LE(largest_difference(laid_out[k], expected[k]), kTolerance);
}

TEST_F(PdExternal, GainTrimsOneOutlet) {
    const auto pd = run_pd({"gain 1 -6"});
    ASSERT_EQ(pd.size(), 3u) << pd_log_;
    const auto gain = static_cast<float>(std::pow(10.0, -6 / 20.0));
    for (size_t i = 0; i < pd[0].size(); ++i)
        ASSERT_NEAR(pd[1][i], pd[0][i] * gain, 1e-6) << "sample " << i;
}

// Each bad message is one line on Pd's console naming what is wrong, and changes nothing.
TEST_F(PdExternal, BadMessagesSayWhyAndChangeNothing) {
    const auto pd = run_pd({"envelope.decay_ms 1e9", "envelope.decy_ms 80",
                            "mapping.frequency.curve cubic", "preset no-such-preset",
                            "actuator no-such-actuator", "gain 5 -6", "trigger 1e9 2"});
    ASSERT_EQ(pd.size(), 3u) << pd_log_;
    for (const std::string expected :
         {"envelope.decay_ms", "did you mean 'envelope.decay_ms'", "cubic", "no-such-preset",
          "no-such-actuator", "gain: outlet 5", "trigger"})
        EXPECT_NE(pd_log_.find(expected), std::string::npos) << expected << "\n" << pd_log_;
    EXPECT_LE(largest_difference(pd[0], render()), kTolerance);
}

// perform() runs the engine and copies: no allocation and no lock, while live and structural
// parameters, a preset, gains and triggers arrive mid-file.
TEST_F(PdExternal, PerformNeitherAllocatesNorLocks) {
    const std::string score =
        "100 tactus-msg post.drive_db 3; 100 tactus-msg envelope.decay_ms 60;"
        "100 tactus-msg mapping.frequency.curve lin; 100 tactus-msg analysis.hop_ms 5;"
        "100 tactus-msg preset four-channel; 100 tactus-msg gain 1 -12;"
        "100 tactus-msg trigger 80 0.5; 100 tactus-msg flutter.weight 0;"
        "100 tactus-msg route 1 band:40-200; 100 tactus-msg route 0 kick+snare;"
        "100 tactus-msg layout " +
        (dir_ / "seat-and-all.toml").string() + ";";
    write_layout("seat-and-all.toml", "band:20-120", "all");
    const auto pd = run_pd({}, score, std::string("LD_PRELOAD=") + TACTUS_PD_GUARD + " ");
    ASSERT_EQ(pd.size(), 3u) << pd_log_;
    for (const char* refused : {"route", "layout"})  // an error would name the message
        EXPECT_EQ(pd_log_.find(refused), std::string::npos) << pd_log_;
    long performs = -1, allocations = -1, locks = -1;
    const size_t at = pd_log_.rfind("perform-guard:");
    ASSERT_NE(at, std::string::npos) << pd_log_;
    ASSERT_EQ(
        std::sscanf(pd_log_.c_str() + at, "perform-guard: performs=%ld allocations=%ld locks=%ld",
                    &performs, &allocations, &locks),
        3);
    EXPECT_GE(performs, static_cast<long>(input_.size() / kPdBlock));
    EXPECT_EQ(allocations, 0);
    EXPECT_EQ(locks, 0);
    EXPECT_GT(largest_difference(pd[0], render()), 0.01f);  // the messages arrived
}

// The help and example patches, as installed beside the external, open with every object made.
TEST_F(PdExternal, HelpAndExamplePatchesOpenCleanly) {
    for (const std::string patch : {"tactus~-help.pd", "tactus~-example.pd"}) {
        const std::string command = host_preload() + TACTUS_PD + " -nogui -batch -noaudio -path " +
                                    TACTUS_PD_DIR + "/.. -open " + TACTUS_PD_DIR + "/" + patch +
                                    " -send \"pd quit\" 2>" + (dir_ / "pd.txt").string();
        ASSERT_EQ(std::system(command.c_str()), 0) << command;
        std::ifstream log(dir_ / "pd.txt");
        const std::string text{std::istreambuf_iterator<char>(log), {}};
        EXPECT_NE(text.find("tactus~ "), std::string::npos) << patch << ": " << text;
        EXPECT_EQ(text.find("couldn't create"), std::string::npos) << patch << ": " << text;
        EXPECT_EQ(text.find("error"), std::string::npos) << patch << ": " << text;
    }
}

}  // namespace
}  // namespace tactus::test
