// The designs made so far in the process, by their exact inputs: a design (a fit, a filter) is a
// function of its inputs alone, so one asked for again is the one made before, bit for bit. An
// engine that prepares again, or builds a pipeline for a structural change, takes the designs
// it had instead of making them anew. Control and setup threads (a mutex no audio thread
// takes); past kCapacity entries the oldest is forgotten.
#pragma once

#include <cstddef>
#include <mutex>
#include <utility>
#include <vector>

namespace tactus {

template <typename Key, typename Design>
class DesignMemo {
  public:
    static constexpr size_t kCapacity = 64;

    // The design for `key`: remembered, or make() (outside the lock), remembered.
    template <typename Make>
    Design get(const Key& key, Make&& make) {
        {
            const std::lock_guard lock(mutex_);
            for (const auto& [k, design] : entries_)
                if (k == key) return design;
        }
        Design made = make();
        const std::lock_guard lock(mutex_);
        if (entries_.size() == kCapacity) entries_.erase(entries_.begin());
        entries_.emplace_back(key, made);
        return made;
    }

  private:
    std::mutex mutex_;
    std::vector<std::pair<Key, Design>> entries_;
};

}  // namespace tactus
