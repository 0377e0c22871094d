// The tactus command line, run as a user runs it: outputs on real files, exit codes, one-line
// errors on stderr, and nothing written (or overwritten) when a run fails.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_cli.hpp"
#include "support/signals.hpp"
#include "support/sounds.hpp"
#include "tactus/analysis/onset_rises.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/params/params.hpp"

namespace {

namespace fs = std::filesystem;
using tactus::test::kAmen;

using tactus::test::Cli;
using tactus::test::csv_numbers;
using tactus::test::info_of;
using Result = tactus::test::CliResult;

std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

TEST_F(Cli, HelpEverywhere) {
    for (const char* command : {"", "render ", "analyze ", "onsets ", "presets ", "placement ",
                                "meter ", "export ", "report ", "actuators "}) {
        const Result r = run(std::string(command) + "--help");
        EXPECT_EQ(r.exit_code, 0) << command;
        EXPECT_NE(r.out.find("Usage"), std::string::npos) << command;
    }
}

TEST_F(Cli, PresetsListsTfdAndParameters) {
    EXPECT_NE(run("presets").out.find("tfd"), std::string::npos);
    const Result params = run("presets --params");
    EXPECT_NE(params.out.find("envelope.decay_ms"), std::string::npos);
}

// A preset saved with --set applied renders the same samples as the preset and the --set.
TEST_F(Cli, SavedPresetRendersBitForBit) {
    const fs::path saved = dir_ / "mine.toml";
    const std::string change = " --preset four-channel --set envelope.decay_ms=90.125";
    Result r = run("presets --save " + saved.string() + change);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run("presets --save " + saved.string() + " --preset tfd");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("already exists"), std::string::npos) << r.err;

    const fs::path a = dir_ / "a.wav", b = dir_ / "b.wav";
    ASSERT_EQ(run("render " + kAmen + " -o " + a.string() + change).exit_code, 0);
    ASSERT_EQ(
        run("render " + kAmen + " -o " + b.string() + " --preset " + saved.string()).exit_code, 0);
    const auto x = tactus::read_mono(a).samples, y = tactus::read_mono(b).samples;
    ASSERT_EQ(x.size(), y.size());
    EXPECT_TRUE(std::equal(x.begin(), x.end(), y.begin()));
    EXPECT_GT(*std::max_element(x.begin(), x.end()), 0.1f);
}

TEST_F(Cli, RenderWritesFloatWavWithChannelsAtInputRate) {
    const fs::path out = dir_ / "amen.vibration.wav";
    const Result r = run("render " + kAmen + " -o " + out.string() + " --channels 3");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const SF_INFO in = info_of(kAmen), written = info_of(out);
    EXPECT_EQ(written.samplerate, in.samplerate);
    tactus::test::expect_input_plus_tail(written.frames, in.frames, in.samplerate);
    EXPECT_EQ(written.channels, 3);
    EXPECT_EQ(written.format & SF_FORMAT_SUBMASK, SF_FORMAT_FLOAT);
    EXPECT_TRUE(r.out.empty()) << "messages belong on stderr";
    expect_no_temporaries();
}

TEST_F(Cli, AnalyzeCsvAndJson) {
    const Result csv = run("analyze " + kAmen);
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    // The header, then how it was made as a comment line (so numpy.genfromtxt(names=True)
    // reads the header: apps/python/tests/test_render.py).
    EXPECT_EQ(csv.out.rfind("time_s,loudness_db,brightness_hz,noisiness,pitch_hz,", 0), 0u)
        << csv.out.substr(0, 200);
    EXPECT_NE(csv.out.find(",onset_time_s,hit_db,hit_brightness_hz,part,part_decided,"
                           "hit_strength_db,frequency_hz,"),
              std::string::npos);
    EXPECT_NE(csv.out.find("\n# tactus=" TACTUS_VERSION "; source=loop_amen_full.flac; "
                           "preset=music; actuator=voice-coil\n"),
              std::string::npos)
        << csv.out.substr(0, 400);
    // Every row names its part; the parts decided are those `tactus onsets` prints, in order
    // (which ends with one more when the input ends before the last onset's part is decided).
    std::istringstream lines(csv.out);
    std::string header, line, decided;
    std::getline(lines, header);
    const size_t part = tactus::test::csv_column(header, "part");
    const size_t part_decided = tactus::test::csv_column(header, "part_decided");
    while (std::getline(lines, line)) {
        if (line.starts_with("#")) continue;
        std::vector<std::string> cells;
        std::istringstream s(line);
        for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
        ASSERT_GT(cells.size(), part_decided);
        EXPECT_TRUE(cells[part] == "kick" || cells[part] == "snare" || cells[part] == "hat" ||
                    cells[part] == "other")
            << line;
        if (cells[part_decided] == "1") decided += cells[part] + " ";
    }
    const Result onsets = run("onsets " + kAmen);
    std::string printed;
    std::istringstream onset_lines(onsets.out);
    for (std::string l; std::getline(onset_lines, l);) printed += l.substr(l.rfind(' ') + 1) + " ";
    EXPECT_TRUE(printed.starts_with(decided)) << decided << "\n" << printed;
    EXPECT_LE(std::count(printed.begin(), printed.end(), ' ') -
                  std::count(decided.begin(), decided.end(), ' '),
              1);
    const auto rows = std::count(csv.out.begin(), csv.out.end(), '\n') - 2;
    const double seconds = static_cast<double>(info_of(kAmen).frames) / info_of(kAmen).samplerate;
    const double hop_s = tactus::Settings{}[tactus::P::analysis_hop_ms] * 1e-3;
    EXPECT_NEAR(rows, seconds / hop_s, 0.02 * rows);  // one row per analysis frame

    const fs::path json = dir_ / "amen.json";
    ASSERT_EQ(run("analyze " + kAmen + " -o " + json.string()).exit_code, 0);
    std::ifstream f(json);
    std::string text((std::istreambuf_iterator<char>(f)), {});
    EXPECT_EQ(text.rfind("{\"tactus\": {\"version\":\"" TACTUS_VERSION "\",\"source\":"
                         "\"loop_amen_full.flac\",\"preset\":\"music\",\"set\":[],",
                         0),
              0u)
        << text.substr(0, 200);
    EXPECT_NE(text.find("\"frames\": [\n{\"time_s\""), std::string::npos);
    EXPECT_NE(text.find("\"frequency_hz\""), std::string::npos);
    EXPECT_NE(text.find("\"part\":\"hat\""), std::string::npos);  // the part by name
    EXPECT_EQ(text.substr(text.size() - 3), "]}\n");
}

// --part-features ends each line with the onset model's numbers, read on every onset of an input
// with the 6-10 kHz band (the Amen break, 44.1 kHz) though parts.drum_min is off and the
// analysis alone would not read them.
TEST_F(Cli, PartFeaturesPrintTheOnsetModelsNumbersWithDrumMinOff) {
    const Result r = run("onsets " + kAmen + " --part-features");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream lines(r.out);
    int count = 0, read = 0;
    for (std::string line; std::getline(lines, line); ++count) {
        std::vector<std::string> fields;
        std::istringstream s(line);
        for (std::string field; s >> field;) fields.push_back(field);
        ASSERT_GT(fields.size(), 4u + tactus::OnsetRises::kCount) << line;
        read += std::all_of(fields.end() - tactus::OnsetRises::kCount, fields.end(),
                            [](const std::string& f) { return std::isfinite(std::stod(f)); });
    }
    EXPECT_GT(count, 20);
    EXPECT_GE(read, 0.9 * count) << r.out;
}

TEST_F(Cli, OnsetsAreAscendingWithTheirPart) {
    const Result r = run("onsets " + kAmen);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream lines(r.out);
    double onset, decided, strength, previous = -1;
    std::string part;
    std::set<std::string> parts;
    int count = 0;
    while (lines >> onset >> decided >> strength >> part) {
        EXPECT_GE(onset, previous);
        EXPECT_GE(decided, onset);
        EXPECT_LT(decided - onset, 0.05);
        EXPECT_LT(strength, 6.0);  // dB LKFS: K-weighting's +4 dB shelf lifts a loud hit past 0
        EXPECT_GT(strength, -80.0);
        parts.insert(part);
        previous = onset;
        ++count;
    }
    EXPECT_TRUE(lines.eof()) << "every line: onset_s decided_s strength_db part";
    EXPECT_GT(count, 20);
    EXPECT_GE(parts.size(), 2u);
    for (const auto& p : parts)
        EXPECT_TRUE(p == "kick" || p == "snare" || p == "hat" || p == "other") << p;
}

TEST_F(Cli, BadInputFailsCleanlyAndWritesNothing) {
    const fs::path out = dir_ / "out.wav";
    const fs::path text = dir_ / "notes.wav";
    std::ofstream(text) << "not audio\n";

    const Result not_audio = run("render " + text.string() + " -o " + out.string());
    EXPECT_NE(not_audio.exit_code, 0);
    EXPECT_NE(not_audio.err.find(text.string()), std::string::npos) << not_audio.err;
    EXPECT_FALSE(fs::exists(out));

    const Result unknown_key =
        run("render " + kAmen + " -o " + out.string() + " --set envelope.decay=100");
    EXPECT_NE(unknown_key.exit_code, 0);
    EXPECT_NE(unknown_key.err.find("did you mean 'envelope.decay_ms'"), std::string::npos)
        << unknown_key.err;
    EXPECT_FALSE(fs::exists(out));

    const Result out_of_range =
        run("render " + kAmen + " -o " + out.string() + " --set envelope.decay_ms=-3");
    EXPECT_NE(out_of_range.exit_code, 0);
    EXPECT_NE(out_of_range.err.find("allowed"), std::string::npos) << out_of_range.err;

    EXPECT_NE(run("render " + kAmen + " -o " + out.string() + " --preset nonesuch").exit_code, 0);
    EXPECT_NE(run("render /no/such/file.wav -o " + out.string()).exit_code, 0);
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, PresetsListsFourChannel) {
    EXPECT_NE(run("presets").out.find("four-channel"), std::string::npos);
}

// A held tone with a soft start has no onset: tfd's pulses leave it silent, and render says so;
// the sustained preset follows its loudness.
TEST_F(Cli, SustainedSoundsWarnWithoutVibrationAndTheSustainedPresetFeelsThem) {
    const double rate = 44100;
    std::vector<float> tone(static_cast<size_t>(3 * rate));
    for (size_t i = 0; i < tone.size(); ++i)
        tone[i] = static_cast<float>(  // 50 ms fades in and out
            0.5 * std::min({1.0, i / (0.05 * rate), (tone.size() - i) / (0.05 * rate)}) *
            std::sin(2 * tactus::test::kTestPi * 440 * i / rate));
    const fs::path input = dir_ / "tone.wav", pulses = dir_ / "tfd.wav", held = dir_ / "held.wav";
    ASSERT_NO_FATAL_FAILURE(tactus::test::write_sound_file(input, tone, rate));
    const auto peak = [](const fs::path& path) {
        const auto x = tactus::read_mono(path).samples;
        float p = 0;
        for (float v : x) p = std::max(p, std::abs(v));
        return p;
    };

    Result r = run("render " + input.string() + " -o " + pulses.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(peak(pulses), 0.0f);
    EXPECT_NE(r.err.find("warning: " + input.string() + ": the input is audible"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("--preset sustained"), std::string::npos) << r.err;

    r = run("render " + input.string() + " -o " + held.string() + " --preset sustained");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    EXPECT_GT(peak(held), 0.05f);
    // Silence stays silent, without a warning.
    ASSERT_NO_FATAL_FAILURE(
        tactus::test::write_sound_file(input, std::vector<float>(tone.size(), 0.0f), rate));
    r = run("render " + input.string() + " -o " + pulses.string() + " --force");
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

// An explosion: a low rumble that starts at once and lasts 2 s. The default preset gives its
// onset one pulse and then nothing, and render, export and report say so in the same line naming
// the preset that follows loudness; that preset vibrates all through the rumble. A drum loop gets
// no warning.
TEST_F(Cli, ARumbleAfterItsOnsetWarnsOnceAndTheSustainedPresetFeelsItThrough) {
    const double rate = 44100;
    const auto at = [&](double seconds) { return static_cast<size_t>(seconds * rate); };
    // Brown noise (integrated white) through two one-pole low-passes at 100 Hz, peak 0.7,
    // 0.3 s fade-out, with 0.3 s of silence either side.
    const std::vector<float> white = tactus::test::white_noise(at(2), 11);
    std::vector<float> rumble(at(2.6), 0.0f);
    const double leak = 1 - 2 * tactus::test::kTestPi * 5 / rate;
    const double low = 1 - std::exp(-2 * tactus::test::kTestPi * 100 / rate);
    double brown = 0, lp1 = 0, lp2 = 0, largest = 0;
    for (size_t i = 0; i < white.size(); ++i) {
        brown = leak * brown + white[i];
        lp1 += low * (brown - lp1);
        lp2 += low * (lp1 - lp2);
        rumble[at(0.3) + i] =
            static_cast<float>(lp2 * std::min(1.0, (white.size() - i) / (0.3 * rate)));
        largest = std::max(largest, std::abs(lp2));
    }
    for (float& x : rumble) x = static_cast<float>(0.7 * x / largest);
    const fs::path input = dir_ / "rumble.wav", pulses = dir_ / "music.wav",
                   held = dir_ / "held.wav";
    ASSERT_NO_FATAL_FAILURE(tactus::test::write_sound_file(input, rumble, rate));
    const auto window_peaks = [&](const fs::path& path, double from_s, double to_s) {
        const auto y = tactus::read_mono(path).samples;
        std::vector<float> peaks;
        for (size_t start = at(from_s); start + at(0.1) <= at(to_s); start += at(0.1)) {
            float p = 0;
            for (size_t i = start; i < start + at(0.1); ++i) p = std::max(p, std::abs(y[i]));
            peaks.push_back(p);
        }
        return peaks;
    };

    Result r = run("render " + input.string() + " -o " + pulses.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("tactus: warning: " + input.string() +
                         ": 1.8 s of sound from 0.5 s on "
                         "gave no vibration: the preset pulses only at onsets; for sustained "
                         "sounds try --preset sustained\n"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;  // and the summary
    EXPECT_NE(r.err.find(", 1 pulses,"), std::string::npos) << r.err;
    EXPECT_GT(window_peaks(pulses, 0.3, 0.4)[0], 0.1f);                        // the onset's pulse
    for (const float p : window_peaks(pulses, 0.6, 2.3)) EXPECT_LT(p, 0.01f);  // then nothing

    r = run("render " + input.string() + " -o " + held.string() + " --preset sustained");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    const std::vector<float> felt = window_peaks(held, 0.3, 2.2);  // all but the fade's end
    ASSERT_EQ(felt.size(), 19u);
    for (const float p : felt) EXPECT_GT(p, 0.2f);  // -14 dBFS and louder, every 100 ms

    r = run("render " + kAmen + " -o " + pulses.string() + " --force");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;

    // A designer exporting the explosion is told the same, once for all its outputs, after
    // they are written (the .ahap's intensity: the onset's pulse, then nothing).
    const fs::path ahap = dir_ / "rumble.ahap", android = dir_ / "rumble.android.json";
    r = run("export " + input.string() + " -o " + ahap.string() + " -o " + android.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string warning = "tactus: warning: " + input.string() +
                                ": 1.8 s of sound from 0.5 s on gave no vibration: the preset "
                                "pulses only at onsets; for sustained sounds try --preset "
                                "sustained\n";
    EXPECT_EQ(r.err.substr(0, warning.size()), warning) << r.err;  // then one line per output
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 3) << r.err;
    EXPECT_NE(r.err.find(android.string() + ": 2.6"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(ahap) && fs::exists(android));
    const fs::path page = dir_ / "rumble.html";  // and so is one looking at its report
    r = run("report " + input.string() + " -o " + page.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, warning + page.string() + ": 9 plots, 1 onsets\n");
    r = run("export " + input.string() + " -o " + ahap.string() + " --force --preset sustained");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    r = run("export " + kAmen + " -o " + ahap.string() + " --force");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

TEST_F(Cli, PlacementReportsAndWritesAPlotCsv) {
    const std::string example =
        std::string(TACTUS_SOURCE_DIR) + "/examples/placement_synthetic.csv";
    const fs::path out = dir_ / "figure2.csv";
    const Result r = run("placement " + example + " -o " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("least variation: 6 mm hole"), std::string::npos) << r.out;
    std::ifstream csv(out);
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "hole_mm,subject,finger,extension_mm,mean_mm,sd_mm,n,depth_mm");
    int rows = 0;
    while (std::getline(csv, line)) ++rows;
    EXPECT_EQ(rows, 45);
}

TEST_F(Cli, PlacementBadFileFailsWithTheLineAndWritesNothing) {
    const fs::path bad = dir_ / "bad.csv", out = dir_ / "out.csv";
    std::ofstream(bad) << "subject,finger,hole_mm,extension_mm\na,index,6,0.8\na,index,7,deep\n";
    const Result r = run("placement " + bad.string() + " -o " + out.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(bad.string() + ":3: extension_mm 'deep' is not a number"),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(fs::exists(out));
    const fs::path good = dir_ / "good.csv";
    std::ofstream(good) << "subject,finger,hole_mm,extension_mm\na,index,6,0.8\n";
    const auto size = fs::file_size(good);
    const Result same = run("placement " + good.string() + " -o " + good.string());
    EXPECT_NE(same.exit_code, 0);
    EXPECT_NE(same.err.find("overwrite the input"), std::string::npos) << same.err;
    EXPECT_EQ(fs::file_size(good), size);
}

TEST_F(Cli, NeverOverwritesTheInput) {
    const fs::path input = dir_ / "in.flac";
    fs::copy_file(kAmen, input);
    const auto size = fs::file_size(input);
    const Result r = run("render " + input.string() + " -o " + input.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("overwrite the input"), std::string::npos) << r.err;
    EXPECT_EQ(fs::file_size(input), size);
}

// Several inputs, one output directory, two workers: each file comes out exactly as a render of
// it alone would (every worker has its own engine), named <stem>.vibration.wav.
TEST_F(Cli, RendersSeveralFilesIntoADirectory) {
    const std::string samples = "/usr/share/sonic-pi/samples/";
    const std::vector<std::string> inputs = {kAmen, samples + "loop_amen.flac",
                                             samples + "bd_808.flac"};
    const fs::path out = dir_ / "out";
    const Result batch = run("render " + inputs[0] + " " + inputs[1] + " " + inputs[2] + " -O " +
                             out.string() + " -j 2");
    ASSERT_EQ(batch.exit_code, 0) << batch.err;
    EXPECT_EQ(names_in(out),
              (std::vector<std::string>{"bd_808.vibration.wav", "loop_amen.vibration.wav",
                                        "loop_amen_full.vibration.wav"}));
    for (const std::string& input : inputs) {
        const fs::path alone = dir_ / "alone.wav";
        ASSERT_EQ(run("render " + input + " -o " + alone.string() + " --force").exit_code, 0);
        const fs::path batched = out / (fs::path(input).stem().string() + ".vibration.wav");
        EXPECT_EQ(info_of(batched).frames, info_of(alone).frames) << input;
        tactus::test::expect_input_plus_tail(info_of(batched).frames, info_of(input).frames,
                                             info_of(input).samplerate);
        const std::vector<float> expected = tactus::read_mono(alone).samples;
        ASSERT_FALSE(expected.empty());
        EXPECT_TRUE(tactus::read_mono(batched).samples == expected) << input;
        EXPECT_NE(batch.err.find(batched.string()), std::string::npos) << batch.err;
    }
}

// One unreadable file fails alone: it is named, gets no output (not even a partial one), the
// others are written, and the exit code says something failed.
TEST_F(Cli, BatchFailureIsReportedAndTheOthersComplete) {
    const fs::path text = dir_ / "notes.wav";
    std::ofstream(text) << "not audio\n";
    const fs::path out = dir_ / "out";
    const Result r = run("render " + kAmen + " " + text.string() +
                         " /usr/share/sonic-pi/samples/loop_amen.flac -O " + out.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(text.string() + ": "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("1 of 3 files failed"), std::string::npos) << r.err;
    EXPECT_EQ(names_in(out), (std::vector<std::string>{"loop_amen.vibration.wav",
                                                       "loop_amen_full.vibration.wav"}));
}

// Every command that writes a file refuses one that exists, names it, leaves it as it was, and
// replaces it with --force: a batch's outputs, the meter's CSV, the placement CSV.
TEST_F(Cli, ExistingOutputsNeedForce) {
    const fs::path out = dir_ / "out", vibration = out / "loop_amen_full.vibration.wav";
    const fs::path meter_csv = dir_ / "meter.csv", placement_csv = dir_ / "placement.csv";
    const std::string placement_input =
        std::string(TACTUS_SOURCE_DIR) + "/examples/placement_synthetic.csv";
    const std::vector<std::pair<std::string, fs::path>> commands = {
        {"render " + kAmen + " -O " + out.string(), vibration},
        {"meter " + vibration.string() + " -o " + meter_csv.string(), meter_csv},
        {"placement " + placement_input + " -o " + placement_csv.string(), placement_csv}};
    for (const auto& [command, output] : commands) {
        ASSERT_EQ(run(command).exit_code, 0) << command;
        const auto size = fs::file_size(output);
        const Result again = run(command);
        EXPECT_NE(again.exit_code, 0) << command;
        EXPECT_NE(again.err.find(output.string() + ": already exists (use --force"),
                  std::string::npos)
            << again.err;
        EXPECT_EQ(fs::file_size(output), size) << command;
        EXPECT_EQ(run(command + " --force").exit_code, 0) << command;
    }
}

// Output names are decided before any audio is read: ambiguous requests write nothing.
TEST_F(Cli, BatchRefusesAmbiguousOutputs) {
    const fs::path flac = dir_ / "take.flac", wav = dir_ / "take.wav", out = dir_ / "out";
    fs::copy_file(kAmen, flac);
    fs::copy_file(kAmen, wav);  // libsndfile reads by content: a FLAC named .wav is still audio

    const Result same_name =
        run("render " + flac.string() + " " + wav.string() + " -O " + out.string());
    EXPECT_NE(same_name.exit_code, 0);
    EXPECT_NE(same_name.err.find("take.vibration.wav: both"), std::string::npos) << same_name.err;

    const Result one_output =
        run("render " + kAmen + " " + flac.string() + " -o " + (dir_ / "x.wav").string());
    EXPECT_NE(one_output.exit_code, 0);
    EXPECT_NE(one_output.err.find("use -O DIR"), std::string::npos) << one_output.err;

    EXPECT_NE(run("render " + kAmen).exit_code, 0);  // neither -o nor -O
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(dir_ / "x.wav"));
}

// ---- Perception: tactus meter, --actuator ----

TEST_F(Cli, MeterAmenThroughTheVoiceCoil) {
    const fs::path vibration = dir_ / "amen.wav", csv = dir_ / "amen.meter.csv";
    const Result render =
        run("render " + kAmen + " -o " + vibration.string() + " --actuator voice-coil");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(render.err.find("warning"), std::string::npos) << render.err;
    const Result r = run("meter " + vibration.string() + " -o " + csv.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // Summary rows: channel, sensation, max dB SL, engaged %, median dB SL (or "not engaged").
    std::istringstream lines(r.out);
    std::string line;
    std::map<std::string, std::pair<double, std::string>> rows;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string channel, sensation, max_db, engaged, median;
        words >> channel >> sensation >> max_db >> engaged;
        std::getline(words, median);
        if (channel == "P" || channel == "NPI" || channel == "NPII" || channel == "NPIII")
            rows[channel] = {std::stod(max_db), median};
    }
    ASSERT_EQ(rows.size(), 4u) << r.out;
    EXPECT_GE(rows["P"].first, 10.0) << r.out;     // the hits engage P
    EXPECT_EQ(rows["NPIII"].first, 0.0) << r.out;  // a voice coil holds no offset
    EXPECT_NE(rows["NPIII"].second.find("not engaged"), std::string::npos);
    std::ifstream f(csv);
    std::string comment, header;  // the header first: CSV readers take their names from it
    std::getline(f, header);
    EXPECT_EQ(header, "time_s,P_sl_db,NPI_sl_db,NPII_sl_db,NPIII_sl_db,combined_sl_db");
    std::getline(f, comment);
    EXPECT_EQ(comment, "# tactus=" TACTUS_VERSION "; source=amen.wav; actuator=voice-coil");
    int count = 0;
    while (std::getline(f, line)) ++count;
    const double seconds =
        static_cast<double>(info_of(vibration).frames) / info_of(vibration).samplerate;
    EXPECT_NEAR(count, seconds / 0.01 + 40, 2);  // every 10 ms, and 0.4 s of tail
    expect_no_temporaries();
}

TEST_F(Cli, ActuatorWarningsAndErrors) {
    const fs::path out = dir_ / "out.wav";
    const Result lra = run("render " + kAmen + " -o " + out.string() + " --actuator lra-175");
    ASSERT_EQ(lra.exit_code, 0) << lra.err;
    EXPECT_NE(lra.err.find("warning: lra-175: fitted to its usable band 150-235 Hz"),
              std::string::npos)
        << lra.err;
    fs::remove(out);

    const Result unknown = run("render " + kAmen + " -o " + out.string() + " --actuator nonesuch");
    EXPECT_NE(unknown.exit_code, 0);
    EXPECT_NE(unknown.err.find("no actuator named 'nonesuch'"), std::string::npos) << unknown.err;
    EXPECT_EQ(std::count(unknown.err.begin(), unknown.err.end(), '\n'), 1);
    EXPECT_FALSE(fs::exists(out));

    const fs::path bad = dir_ / "bad.toml";
    std::ofstream(bad) << "displacement_um = 10\nreference_hz = 100\nband_low_hz = 20\n"
                          "band_high_hz = 500\nq = 3\n";
    const Result invalid = run("meter " + kAmen + " --actuator " + bad.string());
    EXPECT_NE(invalid.exit_code, 0);
    EXPECT_NE(invalid.err.find(bad.string() + ":5:5: q: unknown key"), std::string::npos)
        << invalid.err;

    fs::copy_file(kAmen, dir_ / "in.flac");
    EXPECT_NE(run("meter " + (dir_ / "in.flac").string() + " -o " + (dir_ / "in.flac").string())
                  .exit_code,
              0);
    EXPECT_EQ(fs::file_size(dir_ / "in.flac"), fs::file_size(kAmen));
}

// Energy share of a file's first channel within [low_hz, high_hz].
double band_share(const fs::path& file, double low_hz, double high_hz) {
    const auto audio = tactus::read_mono(file);
    size_t n = 1;
    while (n < audio.samples.size()) n *= 2;
    std::vector<std::complex<double>> x(n);
    for (size_t i = 0; i < audio.samples.size(); ++i) x[i] = audio.samples[i];
    tactus::test::fft(x);
    double in = 0, all = 0;
    for (size_t k = 1; k < n / 2; ++k) {
        const double f = static_cast<double>(k) * audio.sample_rate_hz / static_cast<double>(n);
        const double p = std::norm(x[k]);
        all += p;
        if (f >= low_hz && f <= high_hz) in += p;
    }
    return in / all;
}

// The default preset on an LRA: its vibration inside the usable band, one warning saying so;
// the four-channel preset's flutter, which the LRA cannot play, dropped in that same line.
TEST_F(Cli, LraRenderFitsItsBandWithOneWarning) {
    for (const char* preset : {"tfd", "four-channel"}) {
        const fs::path out = dir_ / (std::string(preset) + ".wav");
        const Result r = run("render " + kAmen + " -o " + out.string() + " --preset " + preset +
                             " --actuator lra-175");
        ASSERT_EQ(r.exit_code, 0) << r.err;
        int warnings = 0;
        for (size_t at = r.err.find("warning"); at != std::string::npos;
             at = r.err.find("warning", at + 1))
            ++warnings;
        EXPECT_EQ(warnings, 1) << r.err;
        const double share = band_share(out, 150, 235);
        std::cout << preset << " on lra-175: " << 100 * share << " % within 150-235 Hz\n";
        EXPECT_GE(share, 0.9) << preset;
        if (std::string(preset) == "four-channel") {
            EXPECT_NE(r.err.find("NPI flutter dropped"), std::string::npos) << r.err;
        }
    }
}

// An ERM is driven by an intensity it can follow: through its model (tactus simulate) the render
// vibrates within its 120-200 Hz, and P is engaged (tactus meter, the same model).
TEST_F(Cli, ErmRenderDrivesItsMotor) {
    const fs::path out = dir_ / "erm.wav", moved = dir_ / "erm.displacement.wav";
    ASSERT_EQ(run("render " + kAmen + " -o " + out.string() + " --actuator erm").exit_code, 0);
    const Result sim = run("simulate " + out.string() + " -o " + moved.string());
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    EXPECT_NE(sim.err.find("rendered for erm"), std::string::npos) << sim.err;
    EXPECT_GE(band_share(moved, 120, 200), 0.9);
    EXPECT_GT(tactus::test::peak(tactus::read_mono(moved).samples), 0.3);
    EXPECT_EQ(run("simulate " + out.string() + " -o " + moved.string()).exit_code, 1);  // exists
    const Result meter = run("meter " + out.string());
    ASSERT_EQ(meter.exit_code, 0) << meter.err;
    std::istringstream rows(meter.out);
    std::string line;
    double p_max = -1;
    while (std::getline(rows, line))
        if (line.rfind("P ", 0) == 0) p_max = std::stod(line.substr(20, 10));
    EXPECT_GT(p_max, 10.0) << meter.out;
    expect_no_temporaries();
}

TEST_F(Cli, AnalyzeSensationColumnsAgreeWithTheMeter) {
    const Result csv = run("analyze " + kAmen + " --actuator voice-coil");
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    std::istringstream rows(csv.out);
    std::string comment, header, line;
    std::getline(rows, header);
    std::getline(rows, comment);
    EXPECT_NE(header.find(",P_sl_db,NPI_sl_db,NPII_sl_db,NPIII_sl_db,combined_sl_db"),
              std::string::npos)
        << header;
    const fs::path vibration = dir_ / "amen.wav", meter_csv = dir_ / "meter.csv";
    ASSERT_EQ(
        run("render " + kAmen + " -o " + vibration.string() + " --actuator voice-coil").exit_code,
        0);
    ASSERT_EQ(run("meter " + vibration.string() + " -o " + meter_csv.string()).exit_code, 0);
    std::ifstream f(meter_csv);
    std::vector<std::vector<double>> metered;  // time_s, four channels, combined
    while (std::getline(f, line))
        if (line[0] != 't' && line[0] != '#') metered.push_back(csv_numbers(line));
    ASSERT_GT(metered.size(), 500u);
    // Every row from 1 to 5 s carries the meter's levels at the row's own time (between its
    // 10 ms readings, interpolated): the two time courses line up.
    int compared = 0;
    double engaged = 0;
    while (std::getline(rows, line)) {
        const std::vector<double> analyzed = csv_numbers(line);
        const double t = analyzed[0];
        if (t < 1.0 || t > 5.0) continue;
        const auto after = std::find_if(metered.begin(), metered.end(),
                                        [&](const auto& r) { return r[0] >= t - 1e-9; });
        ASSERT_TRUE(after != metered.begin() && after != metered.end());
        const auto& b = *(after - 1);
        const auto& a = *after;
        const double w = (t - b[0]) / (a[0] - b[0]);
        for (size_t c = 0; c < 5; ++c)
            ASSERT_NEAR(analyzed[analyzed.size() - 5 + c], b[1 + c] + w * (a[1 + c] - b[1 + c]),
                        0.015)  // the meter's readings are printed to 0.01 dB
                << "column " << c << " at " << t << " s";
        engaged = std::max(engaged, analyzed[analyzed.size() - 5]);
        ++compared;
    }
    EXPECT_GT(compared, 1000);
    EXPECT_GT(engaged, 10.0);  // P engaged
}

}  // namespace
