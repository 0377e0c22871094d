// The analysis of one input, every frame's features in order, as an engine's frames gave them
// (pop_frame, a FrameObserver) with every feature computed (FeatureSet{}). Played back into an
// engine in place of its analysis (Engine::replay_analysis), it renders what analysing the same
// input again would, bit for bit: a change that leaves the analysis as it was (a parameter
// Analyzer::reads() does not name: mapping, synthesis, post-processing) renders without
// analysing the input again. Valid for the same input, sample rate, input channel and the same
// values of the parameters the analysis reads, from input sample 0.
#pragma once

#include <cstdint>
#include <vector>

#include "tactus/analysis/features.hpp"

namespace tactus {

struct RecordedAnalysis {
    std::vector<Features> frames;  // frame ends strictly increasing
    // The input samples it covers: its last frame's end.
    int64_t end_sample() const { return frames.empty() ? 0 : frames.back().frame_end_sample; }
};

}  // namespace tactus
