// Each onset with its drum part and strength, as every front end reports it. The analysis flags
// an onset on the frame that detects it (Features::onset), and decides the part and strength of
// that hit parts.settle_ms later, on a later frame (Features::part_decided;
// analysis/hit_analysis.hpp). OnsetDecisions pairs the two frames, so an onset is reported once,
// when its part is known. An onset whose part is never decided (the next onset or the end of the
// input came first, or the spectrum was not analysed) is reported then, with the part and
// strength as they stood on its own frame. Any thread: never allocates, locks or throws.
#pragma once

#include <cstdint>

#include "tactus/analysis/features.hpp"

namespace tactus {

struct DecidedOnset {
    int64_t onset_sample = 0;    // its estimated start, input samples
    int64_t decided_sample = 0;  // the end of the frame that detected it (its pulse starts):
                                 // `tactus onsets`' decided_s
    int64_t part_sample = 0;     // the end of the frame that decided its part and strength
    DrumPart part = DrumPart::other;
    double strength_db = -120;  // the hit's strongest level by then (Features::hit_strength_db)
    bool part_decided = false;  // false: reported without its part's decision (above)
};

class OnsetDecisions {
  public:
    // What the analysis must compute besides the onsets: the spectrum, parts are read from it,
    // and the loudness, strengths are.
    static constexpr FeatureSet reads() { return group_of(FeatureSource::hit_db); }

    // Every analysis frame, in order. Calls on_onset(const DecidedOnset&) for each onset this
    // frame completes: at most two (an undecided earlier one, and one detected and decided here).
    template <typename OnOnset>
    void add(const Features& f, OnOnset&& on_onset) {
        if (f.onset) {
            finish(on_onset);  // the next onset came first
            pending_ = {.onset_sample = f.onset_sample,
                        .decided_sample = f.frame_end_sample,
                        .part_sample = f.frame_end_sample,
                        .part = f.part,
                        .strength_db = f.hit_strength_db};
            waiting_ = true;
        }
        if (f.part_decided && waiting_) {
            pending_.part_sample = f.frame_end_sample;
            pending_.part = f.part;
            pending_.strength_db = f.hit_strength_db;
            pending_.part_decided = true;
            waiting_ = false;
            on_onset(pending_);
        }
    }
    // The input ended: the onset still waiting for its part, if any.
    template <typename OnOnset>
    void finish(OnOnset&& on_onset) {
        if (!waiting_) return;
        waiting_ = false;
        on_onset(pending_);
    }
    void reset() noexcept { waiting_ = false; }

  private:
    DecidedOnset pending_;
    bool waiting_ = false;
};

}  // namespace tactus
