// Real inputs shared by the benchmarks: the Amen break (Sonic Pi's loop_amen_full.flac) as mono
// samples, and what each stage sees when the default pipeline runs on it (the analysis frames'
// control frames, the vibration before post-processing).
#pragma once

#include <vector>

#include "tactus/core/params.hpp"
#include "tactus/mapping/control_frame.hpp"

namespace tactus::bench {

inline constexpr double kRateHz = 44100.0;
inline constexpr const char* kAmenPath = "/usr/share/sonic-pi/samples/loop_amen_full.flac";

const std::vector<float>& amen();  // read once; its rate is kRateHz
int hop_samples(const Settings& settings = {});

// One control frame per analysis hop of amen(), from the default Analyzer and Mapper.
const std::vector<ControlFrame>& amen_control();
// The Voice's output for amen_control(): the input of post-processing.
const std::vector<float>& amen_vibration();

}  // namespace tactus::bench
