#include "tactus/io/analysis_ahead.hpp"

#include <algorithm>

namespace tactus {

AnalysisAhead::AnalysisAhead(Engine& engine, const ProcessSpec& spec)
    : engine_(engine), channels_(spec.channels) {
    const Engine::AnalysisSetup setup = engine.analysis_setup();
    block_analysis_.prepare(spec, setup.settings, setup.features, setup.input_channel);
    // A block's frames: one a hop, and one more where the grid falls across it.
    const auto frames_per_block = static_cast<size_t>(spec.max_block / analyzer_.hop_samples()) + 2;
    slots_.reserve(kAhead + 1);
    for (int i = 0; i <= kAhead; ++i) {
        slots_.push_back(
            {ChannelBlock(spec.channels, spec.max_block), 0, std::make_shared<RecordedAnalysis>()});
        slots_.back().analysis->frames.reserve(frames_per_block);
    }
    thread_ = std::thread([this] { analyse(); });
}

AnalysisAhead::~AnalysisAhead() {
    {
        const std::lock_guard lock(mutex_);
        stop_ = true;
    }
    changed_.notify_all();
    thread_.join();
    engine_.replay_analysis(nullptr);
}

void AnalysisAhead::give(const float* const* in, int frames) {
    Slot& slot = slots_[static_cast<size_t>(given_ % (kAhead + 1))];
    for (int c = 0; c < channels_; ++c) std::copy_n(in[c], frames, slot.input[c]);
    slot.frames = frames;
    {
        const std::lock_guard lock(mutex_);
        ++given_;
    }
    changed_.notify_all();
}

void AnalysisAhead::run_oldest(const Run& run) {
    Slot& slot = slots_[static_cast<size_t>(taken_ % (kAhead + 1))];
    {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return analysed_ > taken_ || error_; });
        if (error_) std::rethrow_exception(error_);
    }
    engine_.replay_analysis(slot.analysis);
    run(slot.input.data(), slot.frames);
    ++taken_;  // the slot is free once the engine plays the next one back
}

// Analyses the given blocks in turn into their slots' recordings.
void AnalysisAhead::analyse() {
    for (int64_t next = 0;; ++next) {
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] { return stop_ || given_ > next; });
            if (stop_) return;
        }
        Slot& slot = slots_[static_cast<size_t>(next % (kAhead + 1))];
        auto& frames = slot.analysis->frames;
        frames.clear();
        try {
            block_analysis_.process(slot.input.data(), slot.frames,
                                    [&](const Features& f) { frames.push_back(f); });
        } catch (...) {
            const std::lock_guard lock(mutex_);
            error_ = std::current_exception();
        }
        {
            const std::lock_guard lock(mutex_);
            ++analysed_;
        }
        changed_.notify_all();
    }
}

}  // namespace tactus
