#include "batch.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "progress.hpp"

namespace tactus::cli {

std::vector<std::exception_ptr> run_batch(
    size_t count, int jobs, const std::function<int64_t()>& total_frames, const std::string& label,
    const std::function<void(size_t index, const AddFrames& add_frames)>& task) {
    std::vector<std::exception_ptr> errors(count);
    if (count == 0) return errors;
    Progress progress(label);
    const int64_t total = progress.enabled() ? total_frames() : 0;
    std::atomic<size_t> next{0};
    std::atomic<int64_t> frames_done{0};
    std::mutex mutex;
    std::condition_variable finished_changed;
    size_t finished = 0;
    const AddFrames add_frames = [&](int64_t frames) { frames_done += frames; };

    auto worker = [&] {
        for (size_t i; (i = next++) < count;) {
            try {
                task(i, add_frames);
            } catch (...) {
                errors[i] = std::current_exception();
            }
            const std::lock_guard lock(mutex);
            ++finished;
            finished_changed.notify_one();
        }
    };
    std::vector<std::jthread> workers;
    const size_t threads = std::min(static_cast<size_t>(std::max(jobs, 1)), count);
    for (size_t t = 0; t < threads; ++t) workers.emplace_back(worker);

    // This thread draws the bar; the workers only count.
    std::unique_lock lock(mutex);
    while (finished < count) {
        progress.update(std::min(frames_done.load(), total), total);
        finished_changed.wait_for(lock, std::chrono::milliseconds(100));
    }
    progress.update(total, total);
    return errors;
}

}  // namespace tactus::cli
