// tactus export, run as a user runs it, on the Amen break and a 19 ms tick: every file checked
// against its format's specification (structure and limits) and for fidelity: the envelope it
// plays correlates >= 0.95 with the engine's felt envelope (run here in process, through
// run_file and its tail), and every onset the engine found is a transient or an emphasis
// within 5 ms, with the sharpness of the carrier when its part was decided; each onset's drum
// part and strength are those `tactus onsets` prints (AHAP: in its Metadata; Android: beside
// the onsets).
#include <gtest/gtest.h>
#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "support/run_cli.hpp"
#include "tactus/engine/onset_decisions.hpp"
#include "tactus/export/felt_envelope.hpp"
#include "tactus/export/haptic_formats.hpp"
#include "tactus/io/actuator_file.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/preset.hpp"
#include "tactus/perception/threshold.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using tactus::test::Cli;

constexpr double kStepS = tactus::FeltEnvelope::kStepS;
constexpr double kOnsetToleranceS = 0.005;
constexpr double kMinCorrelation = 0.95;

struct Sound {
    const char* name;
    const char* path;
};
void PrintTo(const Sound& sound, std::ostream* out) {
    *out << sound.name;
}
const Sound kSounds[] = {{"amen", "/usr/share/sonic-pi/samples/loop_amen_full.flac"},
                         {"tick", "/usr/share/sonic-pi/samples/elec_tick.flac"}};

// What the engine renders for `input` under the default preset: its felt envelope on the 1 ms grid
// and its onsets, in the input's time, and the vibration itself, lined up with the input.
struct EngineRun {
    std::vector<double> felt;
    std::vector<double> onsets_s;
    std::vector<double> sharpness;              // per onset: its carrier when its part was decided
    std::vector<double> onset_frame_sharpness;  // ... and on its own frame
    std::vector<float> vibration;
    double sample_rate_hz = 0;
};

// `tactus onsets`' lines: onset_s decided_s strength_db part. `decided`: false when the input
// ended before the part could be decided (then printed as it stood on the onset's frame).
struct PrintedOnset {
    double onset_s = 0, strength_db = 0;
    std::string part;
    bool decided = true;
};
std::vector<PrintedOnset> printed_onsets(const std::string& text) {
    std::vector<PrintedOnset> onsets;
    std::istringstream lines(text);
    double decided_s = 0;
    for (PrintedOnset o; lines >> o.onset_s >> decided_s >> o.strength_db >> o.part;)
        onsets.push_back(o);
    return onsets;
}

EngineRun run_engine(const fs::path& input) {
    tactus::Settings settings;
    tactus::apply_preset_file(settings, tactus::resolve_preset(tactus::kDefaultPreset));
    tactus::Engine engine(settings);
    engine.enable_frame_queue();
    std::vector<std::pair<int64_t, double>> carrier;
    EngineRun run;
    std::vector<float> drive;
    tactus::OnsetDecisions decisions;
    const auto on_output = [&](const float* const* v, int n) {
        for (tactus::AnalysisFrame f; engine.pop_frame(f);) {
            carrier.emplace_back(f.control.sample, f.control.frequency_hz);
            if (f.features.onset) {
                run.onsets_s.push_back(static_cast<double>(f.features.onset_sample));
                run.onset_frame_sharpness.push_back(tactus::sharpness_of(f.control.frequency_hz));
            }
            decisions.add(f.features, [&](const tactus::DecidedOnset& o) {
                EXPECT_TRUE(o.part_decided);
                run.sharpness.push_back(tactus::sharpness_of(f.control.frequency_hz));
            });
        }
        drive.insert(drive.end(), v[0], v[0] + n);
    };
    tactus::run_file(input, engine, {.on_output = on_output}, tactus::RunTail::ring_out);
    run.sample_rate_hz = engine.sample_rate_hz();
    for (double& t : run.onsets_s) t /= run.sample_rate_hz;
    run.vibration.assign(drive.begin() + engine.latency(), drive.end());
    tactus::FeltEnvelope envelope(run.sample_rate_hz);
    size_t next = 0;
    double frequency_hz = 0;
    for (size_t i = 0; i < run.vibration.size(); ++i) {
        while (next < carrier.size() && carrier[next].first <= static_cast<int64_t>(i))
            frequency_hz = carrier[next++].second;
        envelope.write(&run.vibration[i], 1, frequency_hz);
    }
    run.felt = envelope.felt();
    return run;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    const size_t n = std::min(a.size(), b.size());
    const double ma = std::accumulate(a.begin(), a.begin() + n, 0.0) / n;
    const double mb = std::accumulate(b.begin(), b.begin() + n, 0.0) / n;
    double ab = 0, aa = 0, bb = 0;
    for (size_t i = 0; i < n; ++i) {
        ab += (a[i] - ma) * (b[i] - mb);
        aa += (a[i] - ma) * (a[i] - ma);
        bb += (b[i] - mb) * (b[i] - mb);
    }
    return ab / std::sqrt(aa * bb);
}

// Linear interpolation of (time, value) points on the 1 ms grid, over [first, last] only.
void draw(std::vector<double>& grid, const std::vector<std::pair<double, double>>& points) {
    for (size_t k = 0; k + 1 < points.size(); ++k) {
        const auto [t0, v0] = points[k];
        const auto [t1, v1] = points[k + 1];
        for (auto i = static_cast<size_t>(std::ceil(t0 / kStepS - 1e-9));
             i < grid.size() && i * kStepS <= t1 + 1e-9; ++i)
            grid[i] = t1 > t0 ? v0 + (v1 - v0) * (i * kStepS - t0) / (t1 - t0) : v1;
    }
}

// Every onset has a time in `times` within kOnsetToleranceS.
void expect_every_onset_in(const std::vector<double>& onsets, std::vector<double> times,
                           const char* what) {
    std::sort(times.begin(), times.end());
    for (const double onset : onsets) {
        const auto at = std::lower_bound(times.begin(), times.end(), onset - kOnsetToleranceS);
        EXPECT_TRUE(at != times.end() && *at <= onset + kOnsetToleranceS)
            << "onset at " << onset << " s has no " << what << " within 5 ms";
    }
}

Json read_json(const fs::path& path) {
    std::ifstream in(path);
    return Json::parse(in);
}

class Export : public Cli, public ::testing::WithParamInterface<Sound> {
  protected:
    fs::path exported(const std::string& extension) {
        const fs::path out = dir_ / (std::string(GetParam().name) + extension);
        const auto r = run("export " + std::string(GetParam().path) + " -o " + out.string());
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return out;
    }
    std::vector<PrintedOnset> onsets() {
        const auto r = run("onsets " + std::string(GetParam().path));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        std::vector<PrintedOnset> printed = printed_onsets(r.out);
        tactus::AudioReader reader{fs::path(GetParam().path)};
        const double end_s = static_cast<double>(reader.frames()) / reader.sample_rate_hz();
        tactus::Settings settings;
        tactus::apply_preset_file(settings, tactus::resolve_preset(tactus::kDefaultPreset));
        const double wait_s =
            1e-3 * (settings[tactus::P::parts_settle_ms] + settings[tactus::P::analysis_hop_ms]);
        for (PrintedOnset& o : printed) o.decided = o.onset_s + wait_s <= end_s;
        return printed;
    }
};

// Each exported onset's part and strength are the printed onset's at the same time. The export
// rings the vibration out after the input, and the silence there can decide one more onset near
// the end that `tactus onsets`, stopping at the last sample, never decides.
void expect_parts_as_printed(const std::vector<double>& times_s,
                             const std::vector<std::string>& parts,
                             const std::vector<double>& strengths_db,
                             const std::vector<PrintedOnset>& printed, const char* what) {
    ASSERT_GE(times_s.size(), printed.size()) << what;
    ASSERT_LE(times_s.size(), printed.size() + 1) << what;
    ASSERT_EQ(parts.size(), times_s.size()) << what;
    ASSERT_EQ(strengths_db.size(), times_s.size()) << what;
    for (size_t i = 0; i < printed.size(); ++i) {
        EXPECT_NEAR(times_s[i], printed[i].onset_s, 1e-4) << what << " onset " << i;
        if (!printed[i].decided) continue;  // the export's tail decides it
        EXPECT_EQ(parts[i], printed[i].part) << what << " onset " << i;
        EXPECT_NEAR(strengths_db[i], printed[i].strength_db, 0.011) << what << " onset " << i;
    }
}

TEST_P(Export, AhapFollowsAppleSpecAndTheFeltEnvelope) {
    const EngineRun engine = run_engine(GetParam().path);
    const Json ahap = read_json(exported(".ahap"));
    EXPECT_EQ(ahap.at("Version").get<double>(), 1.0);
    ASSERT_TRUE(ahap.at("Pattern").is_array());
    std::vector<double> intensity(engine.felt.size(), 0.0), transients, sharpness;
    std::vector<std::pair<double, double>> continuous;  // [begin, end]
    int curves = 0;
    for (const Json& item : ahap["Pattern"]) {
        ASSERT_EQ(item.size(), 1u) << item;
        if (item.contains("Event")) {
            const Json& e = item["Event"];
            const double t = e.at("Time").get<double>();
            EXPECT_GE(t, 0.0);
            for (const Json& p : e.at("EventParameters")) {
                const std::string id = p.at("ParameterID");
                EXPECT_TRUE(id == "HapticIntensity" || id == "HapticSharpness") << id;
                EXPECT_GE(p.at("ParameterValue").get<double>(), 0.0);
                EXPECT_LE(p.at("ParameterValue").get<double>(), 1.0);
            }
            const std::string type = e.at("EventType");
            if (type == "HapticTransient") {
                transients.push_back(t);
                sharpness.push_back(e.at("EventParameters").at(1).at("ParameterValue"));
            } else {
                ASSERT_EQ(type, "HapticContinuous");
                const double d = e.at("EventDuration").get<double>();
                EXPECT_GT(d, 0.0);
                EXPECT_LE(d, tactus::kAhapMaxEventS);  // Core Haptics: at most 30 s
                continuous.emplace_back(t, t + d);
            }
        } else {
            const Json& c = item.at("ParameterCurve");
            const std::string id = c.at("ParameterID");
            ASSERT_TRUE(id == "HapticIntensityControl" || id == "HapticSharpnessControl") << id;
            const Json& points = c.at("ParameterCurveControlPoints");
            EXPECT_GE(points.size(), 2u);
            EXPECT_LE(points.size(), 16u);  // longer curves fail on devices
            const double start = c.at("Time").get<double>();
            std::vector<std::pair<double, double>> drawn;
            double last = 0;
            for (const Json& p : points) {
                const double t = p.at("Time").get<double>(),
                             v = p.at("ParameterValue").get<double>();
                EXPECT_GE(t, last);
                last = t;
                EXPECT_GE(v, id == "HapticIntensityControl" ? 0.0 : -1.0);
                EXPECT_LE(v, 1.0);
                drawn.emplace_back(start + t, v);
            }
            // Inside one continuous event.
            EXPECT_TRUE(std::any_of(continuous.begin(), continuous.end(),
                                    [&](const auto& span) {
                                        return start >= span.first - 1e-9 &&
                                               start + last <= span.second + 1e-4;
                                    }))
                << "curve at " << start;
            if (id == "HapticIntensityControl") {
                draw(intensity, drawn);
                ++curves;
            }
        }
    }
    // The continuous events cover the vibration, end to end.
    ASSERT_FALSE(continuous.empty());
    EXPECT_EQ(continuous.front().first, 0.0);
    for (size_t i = 1; i < continuous.size(); ++i)
        EXPECT_NEAR(continuous[i].first, continuous[i - 1].second, 1e-4);
    EXPECT_NEAR(continuous.back().second, engine.felt.size() * kStepS, 0.002);
    const double r = correlation(intensity, engine.felt);
    std::cout << GetParam().name << ".ahap: " << curves << " intensity curves, "
              << transients.size() << " transients for " << engine.onsets_s.size()
              << " onsets, correlation with the felt envelope " << r << '\n';
    EXPECT_GE(r, kMinCorrelation);
    expect_every_onset_in(engine.onsets_s, transients, "HapticTransient");
    // A transient's sharpness: the carrier when its hit's part was decided, not on the onset's
    // own frame (where the carrier may still glide).
    ASSERT_EQ(sharpness.size(), engine.sharpness.size());
    int moved = 0;
    for (size_t i = 0; i < sharpness.size(); ++i) {
        EXPECT_NEAR(sharpness[i], engine.sharpness[i], 0.00051) << "transient " << i;
        moved += std::abs(engine.sharpness[i] - engine.onset_frame_sharpness[i]) > 0.001;
    }
    std::cout << GetParam().name << ".ahap: " << moved << " of " << sharpness.size()
              << " transients sharper or duller than on their onset's frame\n";
    // Each onset's part and strength, in the Metadata (an event has no field for them).
    std::vector<double> times, strengths;
    std::vector<std::string> parts;
    for (const Json& o : ahap.at("Metadata").at("Onsets")) {
        times.push_back(o.at("Time"));
        parts.push_back(o.at("Part"));
        strengths.push_back(o.at("StrengthDB"));
    }
    EXPECT_EQ(times, transients);
    expect_parts_as_printed(times, parts, strengths, onsets(), "AHAP Metadata");
}

TEST_P(Export, HapticFollowsMetaSpecAndTheFeltEnvelope) {
    const EngineRun engine = run_engine(GetParam().path);
    const Json haptic = read_json(exported(".haptic"));
    EXPECT_EQ(haptic.at("version").at("major").get<int>(), 1);
    EXPECT_TRUE(haptic.at("metadata").at("editor").get<std::string>().starts_with("tactus"));
    const Json& envelopes = haptic.at("signals").at("continuous").at("envelopes");
    const Json& amplitude = envelopes.at("amplitude");
    ASSERT_GE(amplitude.size(), 2u);
    std::vector<std::pair<double, double>> points;
    std::vector<double> emphases, emphasis_frequency;
    double last = 0;
    for (const Json& p : amplitude) {
        const double t = p.at("time").get<double>(), a = p.at("amplitude").get<double>();
        EXPECT_GE(t, last);  // non-decreasing
        last = t;
        EXPECT_GE(a, 0.0);
        EXPECT_LE(a, 1.0);
        points.emplace_back(t, a);
        if (p.contains("emphasis")) {
            const double ea = p["emphasis"].at("amplitude").get<double>();
            const double ef = p["emphasis"].at("frequency").get<double>();
            EXPECT_GE(ea, a);  // emphasis never below its breakpoint
            EXPECT_LE(ea, 1.0);
            EXPECT_GE(ef, 0.0);
            EXPECT_LE(ef, 1.0);
            emphases.push_back(t);
            emphasis_frequency.push_back(ef);
        }
    }
    const Json& frequency = envelopes.at("frequency");
    double last_f = 0;
    for (const Json& p : frequency) {
        const double t = p.at("time").get<double>(), f = p.at("frequency").get<double>();
        EXPECT_GE(t, last_f);
        last_f = t;
        EXPECT_GE(f, 0.0);
        EXPECT_LE(f, 1.0);
    }
    EXPECT_LE(last_f, last);  // the frequency envelope ends with the amplitude's
    std::vector<double> drawn(engine.felt.size(), 0.0);
    draw(drawn, points);
    const double r = correlation(drawn, engine.felt);
    std::cout << GetParam().name << ".haptic: " << amplitude.size() << " breakpoints, "
              << emphases.size() << " emphases, correlation " << r << '\n';
    EXPECT_GE(r, kMinCorrelation);
    expect_every_onset_in(engine.onsets_s, emphases, "emphasis");
    // Its frequency: the carrier when the hit's part was decided (one emphasis per onset here).
    ASSERT_EQ(emphases.size(), engine.sharpness.size());
    for (size_t i = 0; i < emphases.size(); ++i)
        EXPECT_NEAR(emphasis_frequency[i], engine.sharpness[i], 0.00051) << "emphasis " << i;
}

// The weakest amplitude felt on a phone's LRA (lra-175), worked out here from its profile and the P
// channel's closed form at its resonance (2.9 cm2, 1 s: the default contact area, full temporal
// summation): 0.14 um over 12 um x 0.7 (max_drive) = 0.017 of full drive, amplitude 5 of 255.
int lowest_felt_android_amplitude() {
    const tactus::ActuatorProfile lra =
        tactus::load_actuator(tactus::resolve_actuator(tactus::kAndroidActuator));
    const double threshold_um = std::pow(10.0, tactus::perception::p_threshold_db(175.0) / 20.0);
    return static_cast<int>(
        std::ceil(255 * threshold_um / (lra.displacement_um_at(175.0) * lra.max_drive)));
}

TEST_P(Export, AndroidWaveformIsReadyForCreateWaveform) {
    const EngineRun engine = run_engine(GetParam().path);
    const Json w = read_json(exported(".android.json"));
    EXPECT_EQ(w.at("api_level").get<int>(), 26);
    const auto timings = w.at("timings").get<std::vector<int64_t>>();
    const auto amplitudes = w.at("amplitudes").get<std::vector<int>>();
    ASSERT_EQ(timings.size(), amplitudes.size());
    std::vector<double> drawn;
    for (size_t i = 0; i < timings.size(); ++i) {
        EXPECT_GT(timings[i], 0);
        EXPECT_GE(amplitudes[i], 0);
        EXPECT_LE(amplitudes[i], 255);
        drawn.insert(drawn.end(), static_cast<size_t>(timings[i]), amplitudes[i] / 255.0);
    }
    EXPECT_EQ(static_cast<int64_t>(drawn.size()), w.at("duration_ms").get<int64_t>());
    EXPECT_NEAR(static_cast<double>(drawn.size()), engine.felt.size() * kStepS * 1e3, 2);
    // Each step plays the felt envelope as exported (over its full scale, clipped at 1) as the
    // step resolves it: its RMS over the step (0 below the floor); and the steps follow the
    // envelope itself, though no step is shorter than 20 ms.
    const double full_scale = w.at("metadata").at("felt_full_scale").get<double>();
    std::vector<double> exported(engine.felt.size()), resolved(engine.felt.size());
    for (size_t i = 0; i < exported.size(); ++i)
        exported[i] = std::min(1.0, engine.felt[i] / full_scale);
    for (size_t i = 0, first = 0; i < timings.size(); ++i) {
        const size_t last = std::min(exported.size(), first + static_cast<size_t>(timings[i]));
        double energy = 0;
        for (size_t k = first; k < last; ++k) energy += exported[k] * exported[k];
        for (size_t k = first; k < last; ++k)
            resolved[k] = std::sqrt(energy / static_cast<double>(last - first));
        first = last;
    }
    const double r = correlation(drawn, resolved), r_felt = correlation(drawn, exported);
    std::cout << GetParam().name << ".android.json: " << timings.size() << " steps, correlation "
              << r << " with the felt envelope over each step, " << r_felt << " step by step\n";
    EXPECT_GE(r, kMinCorrelation);
    EXPECT_GE(r_felt, 0.85);
    std::vector<double> onsets_s;
    for (const double ms : w.at("onsets_ms").get<std::vector<double>>())
        onsets_s.push_back(ms / 1e3);
    expect_parts_as_printed(onsets_s, w.at("onset_parts").get<std::vector<std::string>>(),
                            w.at("onset_strengths_db").get<std::vector<double>>(), onsets(),
                            "Android");
}

// BasicEnvelopeBuilder (API 36): intensity and sharpness 0-1, each control point at least 20 ms
// after the one before, the last at zero intensity; drawn from 0 at time 0 through the points,
// the envelope follows the felt one as closely as 20 ms ramps can (a hit's attack takes a few ms:
// its peak comes up to 20 ms late), and reaches its peak.
TEST_P(Export, AndroidEnvelopeIsReadyForBasicEnvelopeBuilder) {
    const EngineRun engine = run_engine(GetParam().path);
    const Json e = read_json(exported(".envelope.json"));
    EXPECT_EQ(e.at("api_level").get<int>(), 36);
    const Json& points = e.at("control_points");
    ASSERT_GE(points.size(), 2u);
    std::vector<std::pair<double, double>> drawn{{0.0, 0.0}};
    int64_t total_ms = 0;
    for (const Json& p : points) {
        for (const char* key : {"intensity", "sharpness"}) {
            EXPECT_GE(p.at(key).get<double>(), 0.0) << p;
            EXPECT_LE(p.at(key).get<double>(), 1.0) << p;
        }
        EXPECT_GE(p.at("duration_ms").get<int64_t>(), tactus::kAndroidMinStepMs) << p;
        total_ms += p.at("duration_ms").get<int64_t>();
        drawn.emplace_back(static_cast<double>(total_ms) * 1e-3, p.at("intensity").get<double>());
    }
    EXPECT_EQ(points.back().at("intensity").get<double>(), 0.0) << "ends at zero intensity";
    EXPECT_EQ(total_ms, e.at("duration_ms").get<int64_t>());
    EXPECT_NEAR(static_cast<double>(total_ms), engine.felt.size() * kStepS * 1e3, 45);
    const double full_scale = e.at("metadata").at("felt_full_scale").get<double>();
    std::vector<double> felt(engine.felt.size()), grid(engine.felt.size(), 0.0);
    for (size_t i = 0; i < felt.size(); ++i) felt[i] = std::min(1.0, engine.felt[i] / full_scale);
    draw(grid, drawn);
    const double r = correlation(grid, felt);
    std::cout << GetParam().name << ".envelope.json: " << points.size()
              << " control points, correlation " << r << " with the felt envelope\n";
    if (engine.felt.size() * kStepS > 1) {  // a short tick is mostly its attack
        EXPECT_GE(r, 0.75);
    }
    double highest = 0;
    for (const Json& p : points) highest = std::max(highest, p.at("intensity").get<double>());
    EXPECT_GE(highest, 0.9 * *std::max_element(felt.begin(), felt.end()));
    std::vector<double> onsets_s, strengths_db;
    std::vector<std::string> parts;
    for (const Json& o : e.at("onsets")) {
        onsets_s.push_back(o.at("time_ms").get<double>() / 1e3);
        parts.push_back(o.at("part"));
        strengths_db.push_back(o.at("strength_db"));
    }
    expect_parts_as_printed(onsets_s, parts, strengths_db, onsets(), "Android envelope");
}

// A phone without amplitude control plays every amplitude but 0 at full strength: nothing below
// what its actuator makes felt is written, so the motor stops where the vibration fades (a tail
// of amplitude 1 buzzed to the end), and no step is shorter than a phone resolves (20 ms).
TEST_P(Export, AndroidSwitchesTheMotorOffBelowTheFeltFloor) {
    const EngineRun engine = run_engine(GetParam().path);
    const Json w = read_json(exported(".android.json"));
    const auto timings = w.at("timings").get<std::vector<int64_t>>();
    const auto amplitudes = w.at("amplitudes").get<std::vector<int>>();
    const int lowest = lowest_felt_android_amplitude();
    EXPECT_EQ(w.at("lowest_amplitude").get<int>(), lowest);
    EXPECT_EQ(w.at("min_step_ms").get<int>(), 20);
    std::vector<int> drawn;
    int64_t on_ms = 0;
    for (size_t i = 0; i < timings.size(); ++i) {
        EXPECT_GE(timings[i], 20) << "step " << i;
        if (amplitudes[i] != 0) {
            EXPECT_GE(amplitudes[i], lowest) << "step " << i;
        }
        on_ms += amplitudes[i] > 0 ? timings[i] : 0;
        drawn.insert(drawn.end(), static_cast<size_t>(timings[i]), amplitudes[i]);
    }
    ASSERT_FALSE(amplitudes.empty());
    EXPECT_EQ(amplitudes.back(), 0) << "the motor runs to the end";
    // Wherever the exported envelope stays below the floor for 40 ms, the motor is off after its
    // first 20 ms (a step may reach 20 ms past a fade).
    const double full_scale = w.at("metadata").at("felt_full_scale").get<double>();
    const double floor = (lowest - 0.5) / 255.0;
    size_t quiet_ms = 0, buzzing_ms = 0;
    for (size_t i = 0; i < std::min(drawn.size(), engine.felt.size()); ++i) {
        const bool below = engine.felt[i] / full_scale < floor;
        size_t run = 0;
        while (below && i + run < engine.felt.size() && run < 40 &&
               engine.felt[i + run] / full_scale < floor)
            ++run;
        if (run < 40) continue;
        ++quiet_ms;
        buzzing_ms += i + 20 < drawn.size() && drawn[i + 20] != 0;
    }
    std::cout << GetParam().name << ".android.json: motor on "
              << 100.0 * static_cast<double>(on_ms) / static_cast<double>(drawn.size())
              << " % of the time, " << timings.size() << " steps; " << buzzing_ms << " of "
              << quiet_ms << " ms below the floor on\n";
    EXPECT_EQ(buzzing_ms, 0u);
}

// The comments of an Ogg Vorbis file, read from its comment header as the Vorbis I spec lays
// it out (packet type 3, "vorbis", vendor, then length-prefixed TAG=value strings).
std::vector<std::string> vorbis_comments(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const size_t at = bytes.find("\x03vorbis");
    if (at == std::string::npos) return {};
    size_t p = at + 7;
    const auto u32 = [&] {
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i)
            v |= static_cast<uint32_t>(static_cast<uint8_t>(bytes[p + i])) << (8 * i);
        p += 4;
        return v;
    };
    p += u32();  // vendor
    std::vector<std::string> comments(u32());
    for (auto& c : comments) {
        const uint32_t n = u32();
        c = bytes.substr(p, n);
        p += n;
    }
    return comments;
}

TEST_P(Export, OggCarriesTheSoundAndTheVibrationForAndroid) {
    const EngineRun engine = run_engine(GetParam().path);
    const fs::path ogg = exported(".ogg");
    const auto comments = vorbis_comments(ogg);
    EXPECT_NE(std::find(comments.begin(), comments.end(), "ANDROID_HAPTIC=1"), comments.end());
    SF_INFO info{};
    SNDFILE* file = sf_open(ogg.c_str(), SFM_READ, &info);
    ASSERT_NE(file, nullptr) << sf_strerror(nullptr);
    tactus::AudioReader source(GetParam().path);
    EXPECT_EQ(info.channels, source.channels() + 1);  // the haptic channel last
    EXPECT_EQ(info.samplerate, static_cast<int>(source.sample_rate_hz()));
    std::vector<float> frames(static_cast<size_t>(info.frames * info.channels));
    sf_readf_float(file, frames.data(), info.frames);
    sf_close(file);
    // The haptic channel is the engine's vibration, lined up with the sound (Vorbis is lossy).
    EXPECT_NEAR(static_cast<double>(info.frames), static_cast<double>(engine.vibration.size()), 1);
    std::vector<double> haptic, rendered;
    for (sf_count_t i = 0; i < std::min<sf_count_t>(info.frames, engine.vibration.size()); ++i) {
        haptic.push_back(frames[i * info.channels + info.channels - 1]);
        rendered.push_back(engine.vibration[i]);
    }
    const double r = correlation(haptic, rendered);
    // And the sound is the input's first channel.
    const tactus::MonoAudio mono = tactus::read_mono(GetParam().path);
    std::vector<double> sound, input;
    for (size_t i = 0; i < mono.samples.size(); ++i) {
        double mean = 0;
        for (int c = 0; c + 1 < info.channels; ++c) mean += frames[i * info.channels + c];
        sound.push_back(mean / (info.channels - 1));
        input.push_back(mono.samples[i]);
    }
    const double rs = correlation(sound, input);
    std::cout << GetParam().name << ".ogg: haptic channel vs render " << r << ", sound vs input "
              << rs << '\n';
    EXPECT_GE(r, 0.95);
    EXPECT_GE(rs, 0.95);
}

INSTANTIATE_TEST_SUITE_P(Sounds, Export, ::testing::ValuesIn(kSounds),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_F(Cli, ExportRefusesAnUnknownFormatBeforeReadingAudio) {
    const auto r =
        run("export " + std::string(kSounds[0].path) + " -o " + (dir_ / "x.wav").string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("x.wav: unknown export format"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::is_empty(dir_ / "") || !fs::exists(dir_ / "x.wav"));
}

// One render feeds one .ogg and each output once: a second .ogg or a repeated name is refused
// before any audio is read, and nothing is written.
TEST_F(Cli, ExportRefusesASecondOggAndARepeatedOutput) {
    const std::string input = kSounds[0].path;
    const fs::path a = dir_ / "a.ogg", b = dir_ / "b.ogg", c = dir_ / "c.ahap";
    auto r = run("export " + input + " -o " + a.string() + " -o " + b.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("b.ogg: an export writes one .ogg"), std::string::npos) << r.err;
    r = run("export " + input + " -o " + c.string() + " -o " + c.string());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find("c.ahap: named twice"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(a) || fs::exists(b) || fs::exists(c));
    expect_no_temporaries();
}

}  // namespace

namespace {

std::vector<double> transient_intensities(const Json& ahap) {
    std::vector<double> v;
    for (const Json& item : ahap.at("Pattern"))
        if (item.contains("Event") && item["Event"].at("EventType") == "HapticTransient")
            v.push_back(item["Event"].at("EventParameters").at(0).at("ParameterValue"));
    return v;
}

// numpy.percentile's default: linear between ranks.
double percentile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    const double rank = p / 100 * static_cast<double>(v.size() - 1);
    const auto below = static_cast<size_t>(rank);
    const size_t above = std::min(v.size() - 1, below + 1);
    return v[below] + (rank - static_cast<double>(below)) * (v[above] - v[below]);
}

// --normalise pNN puts the NN-th percentile of the hits at full scale (louder ones clip at 1),
// --gain-db scales after it, by default p99; each file says so in its description.
TEST_F(Cli, ExportNormalisesToAPercentileOfTheHitsWithAGain) {
    const std::string input = kSounds[0].path;
    const fs::path peak = dir_ / "peak.ahap", p90 = dir_ / "p90.ahap", plain = dir_ / "plain.ahap",
                   android = dir_ / "p90.android.json";
    ASSERT_EQ(run("export " + input + " -o " + peak.string() + " --normalise peak").exit_code, 0);
    ASSERT_EQ(run("export " + input + " -o " + p90.string() + " -o " + android.string() +
                  " --normalise p90 --gain-db -3")
                  .exit_code,
              0);
    ASSERT_EQ(run("export " + input + " -o " + plain.string()).exit_code, 0);
    const Json by_peak = read_json(peak), by_p90 = read_json(p90), by_default = read_json(plain);
    const auto at_peak = transient_intensities(by_peak), at_p90 = transient_intensities(by_p90),
               at_default = transient_intensities(by_default);
    ASSERT_EQ(at_p90.size(), at_peak.size());
    ASSERT_GE(at_peak.size(), 20u);
    EXPECT_EQ(*std::max_element(at_peak.begin(), at_peak.end()), 1.0);
    const double gain = std::pow(10.0, -3.0 / 20), p90_of_peak = percentile(at_peak, 90),
                 p99_of_peak = percentile(at_peak, 99);
    int clipped = 0;
    for (size_t i = 0; i < at_peak.size(); ++i) {
        // Both files rounded to 0.001: the peak file's rounding, of the value and of the
        // percentile read from it, carries over scaled.
        const auto near = [&](double exported, double scale) {
            const double expected = std::min(1.0, at_peak[i] * scale);
            const double rounding =
                0.0005 + expected * 0.0005 * (1 / at_peak[i] + scale / (gain / p90_of_peak));
            EXPECT_NEAR(exported, expected, rounding) << "transient " << i;
        };
        near(at_p90[i], gain / p90_of_peak);
        near(at_default[i], 1 / p99_of_peak);
        clipped += at_p90[i] == 1.0;
    }
    EXPECT_GE(clipped, 1);
    std::cout << "amen: p90 of the transients " << p90_of_peak << " of the peak; median "
              << percentile(at_peak, 50) << " (peak) -> " << percentile(at_p90, 50)
              << " (p90, -3 dB), " << percentile(at_default, 50) << " (p99, default)\n";
    const std::string description = by_p90.at("Metadata").at("Description");
    EXPECT_NE(description.find("p90 of the hits' felt peaks"), std::string::npos) << description;
    EXPECT_NE(description.find("gain -3.0 dB"), std::string::npos) << description;
    EXPECT_NE(by_default.at("Metadata").at("Description").get<std::string>().find("p99"),
              std::string::npos);
    EXPECT_NE(
        by_peak.at("Metadata").at("Description").get<std::string>().find("the peak is full scale"),
        std::string::npos);
    EXPECT_EQ(read_json(android).at("metadata").at("description"), description);
}

TEST_F(Cli, ExportRefusesABadNormalisationBeforeReadingAudio) {
    const std::string input = kSounds[0].path;
    const fs::path out = dir_ / "x.ahap";
    for (const char* bad : {"--normalise p101", "--normalise loud", "--gain-db 60"}) {
        const auto r = run("export " + input + " -o " + out.string() + " " + bad);
        EXPECT_NE(r.exit_code, 0) << bad;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(std::string(bad).substr(0, std::string(bad).find(' '))),
                  std::string::npos)
            << r.err;
        EXPECT_FALSE(fs::exists(out));
    }
    expect_no_temporaries();
}

// With a layout each actuator output gets its own file of each format, named by the output,
// each its route's: a kick output's onsets are the kicks `tactus onsets` names, a snare output's
// the snares; the one .ogg carries both outputs as its haptic channels. An .ogg with more
// outputs than Android plays is refused before anything is written.
TEST_F(Cli, ExportWithALayoutWritesEachOutputsFilesAndOneOgg) {
    const std::string amen = "/usr/share/sonic-pi/samples/loop_amen_full.flac";
    std::ofstream(dir_ / "drums.toml") << "[[output]]\nname = \"kick\"\nroute = \"kick\"\n"
                                          "[[output]]\nname = \"snare\"\nroute = \"snare\"\n";
    const fs::path out = dir_ / "amen";
    const auto r = run("export " + amen + " -o " + out.string() + ".ahap -o " + out.string() +
                       ".envelope.json -o " + out.string() + ".ogg --layout " +
                       (dir_ / "drums.toml").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(fs::exists(out.string() + ".ahap"));
    const auto printed = run("onsets " + amen);
    std::map<std::string, int> named;
    for (const PrintedOnset& o : printed_onsets(printed.out)) ++named[o.part];
    for (const std::string part : {"kick", "snare"}) {
        const Json ahap = read_json(out.string() + "." + part + ".ahap");
        std::vector<std::string> parts;
        for (const Json& onset : ahap.at("Metadata").at("Onsets"))
            parts.push_back(onset.at("Part"));
        EXPECT_GE(static_cast<int>(parts.size()), named[part]) << part;
        EXPECT_LE(static_cast<int>(parts.size()), named[part] + 1)
            << part << ": the tail may decide one more";
        for (const std::string& p : parts) EXPECT_EQ(p, part);
        const Json envelope = read_json(out.string() + "." + part + ".envelope.json");
        EXPECT_EQ(envelope.at("onsets").size(), parts.size()) << part;
    }
    const auto comments = vorbis_comments(out.string() + ".ogg");
    EXPECT_NE(std::find(comments.begin(), comments.end(), "ANDROID_HAPTIC=2"), comments.end());
    SF_INFO info{};
    SNDFILE* file = sf_open((out.string() + ".ogg").c_str(), SFM_READ, &info);
    ASSERT_NE(file, nullptr);
    sf_close(file);
    EXPECT_EQ(info.channels, tactus::AudioReader(amen).channels() + 2);

    const auto refused = run("export " + amen + " -o " + (dir_ / "four.ogg").string() + " -o " +
                             (dir_ / "four.ahap").string() + " --layout column-4");
    EXPECT_NE(refused.exit_code, 0);
    EXPECT_NE(refused.err.find("at most 2 haptic channels"), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(dir_ / "four.bottom.ahap"));
}

}  // namespace
