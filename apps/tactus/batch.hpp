// Runs one task per file on N worker threads (one file per worker at a time), with one progress
// bar for the whole batch by total frames. A task that throws fails alone: its error is kept and
// the other tasks complete.
#pragma once

#include <cstdint>
#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace tactus::cli {

// Counts frames done by one task towards the batch's progress bar (thread-safe).
using AddFrames = std::function<void(int64_t frames)>;

// Calls task(i, add_frames) for every i in [0, count) on min(jobs, count) threads; returns one
// exception per task (null when it succeeded). `total_frames` sizes the bar; it is called only
// when the bar is drawn (stderr is a terminal).
std::vector<std::exception_ptr> run_batch(
    size_t count, int jobs, const std::function<int64_t()>& total_frames, const std::string& label,
    const std::function<void(size_t index, const AddFrames& add_frames)>& task);

}  // namespace tactus::cli
