// An offline run's analysis on a thread of its own, a few blocks ahead of the engine: each block
// of input is analysed there as the engine's pipeline would analyse it (BlockAnalysis prepared
// with Engine::analysis_setup()), and the engine synthesises the block from those frames
// (Engine::replay_analysis: bit for bit what its own analysis gives, recorded_analysis.hpp). The
// analysis is about two thirds of Engine::process (bench/results.md), so on two cores a long
// render takes about that share of the engine's time instead of all of it. The setup thread that
// runs the engine calls everything; allocates.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "tactus/analysis/analyzer.hpp"
#include "tactus/dsp/process_spec.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"
#include "tactus/io/run_file.hpp"

namespace tactus {

class AnalysisAhead {
  public:
    // Blocks analysed ahead of the one the engine runs (each spec.max_block frames at most).
    static constexpr int kAhead = 3;

    // `engine`: prepared at `spec`, not replaying; used until the destructor.
    AnalysisAhead(Engine& engine, const ProcessSpec& spec);
    // Stops the analysis; the engine plays nothing back any more (its own analysis has not
    // heard the input: a run ends with this).
    ~AnalysisAhead();
    AnalysisAhead(const AnalysisAhead&) = delete;
    AnalysisAhead& operator=(const AnalysisAhead&) = delete;

    // Blocks given and not yet run.
    int queued() const { return static_cast<int>(given_ - taken_); }
    // A copy of `frames` (<= spec.max_block) frames of input goes to the analysis; while
    // kAhead + 1 blocks are queued, run_oldest() must come first.
    void give(const float* const* in, int frames);
    // Waits for the oldest queued block's analysis, then calls run(in, frames) with that block
    // while the engine plays its frames back; rethrows what the analysis threw.
    using Run = std::function<void(const float* const* in, int frames)>;
    void run_oldest(const Run& run);

  private:
    struct Slot {
        ChannelBlock input;
        int frames = 0;
        std::shared_ptr<RecordedAnalysis> analysis;
    };
    void analyse();  // the analysis thread

    Engine& engine_;
    Analyzer analyzer_;
    BlockAnalysis block_analysis_{analyzer_};
    int channels_;
    std::vector<Slot> slots_;  // in turn: given, analysed, run
    std::mutex mutex_;
    std::condition_variable changed_;
    int64_t given_ = 0, analysed_ = 0, taken_ = 0;  // since the start; given_ and taken_ are
                                                    // the setup thread's, analysed_ mutex_'s
    bool stop_ = false;
    std::exception_ptr error_;
    std::thread thread_;
};

}  // namespace tactus
