// Real inputs shared by the benchmarks: the Amen break (Sonic Pi's loop_amen_full.flac) as mono
// samples, and what each stage sees when the default Engine runs on it at kRateHz (the analysis
// frames' features and control frames, the vibration before post-processing). As in the
// engine, synthesis and post-processing run at the internal rate, kRateHz / rate_divisor().
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tactus/analysis/features.hpp"
#include "tactus/mapping/control_frame.hpp"

namespace tactus::bench {

inline constexpr double kRateHz = 44100.0;
inline constexpr const char* kAmenPath = "/usr/share/sonic-pi/samples/loop_amen_full.flac";

const std::vector<float>& amen();  // read once; its rate is kRateHz

// Read once from the default Engine prepared at kRateHz: its analysis frames per second, and
// input samples per internal (synthesis and post-processing) sample.
double frame_rate_hz();
int rate_divisor();
double internal_rate_hz();  // kRateHz / rate_divisor() (11.025 kHz)

// amen() at the analysis rate (Analyzer::kAnalysisRateHz), through the Analyzer's Resampler,
// and the default analysis hop there: what the feature extractors read.
const std::vector<float>& amen_analysis();
int analysis_hop_samples();

// The default Analyzer's features for each analysis hop of amen().
const std::vector<Features>& amen_features();
// One control frame per analysis hop: amen_features() through the default Mapper.
const std::vector<ControlFrame>& amen_control();
// Internal samples the Voice renders during each hop, before that hop's control frame is
// applied, as Engine::process schedules them (about kRateHz / frame_rate_hz() / rate_divisor()).
const std::vector<int>& internal_samples_per_hop();
// The Voice's output for amen_control() at internal_rate_hz(): the input of post-processing.
const std::vector<float>& amen_vibration();

// Reports `count` items per iteration, labelled "items = <what>".
void set_items(benchmark::State& state, size_t count, const char* what);
// Reports `samples` (at kRateHz) items per iteration and x real time: audio seconds per wall
// second.
void set_real_time(benchmark::State& state, size_t samples);

}  // namespace tactus::bench
