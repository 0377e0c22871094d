// The parameter values a host asked for, and their hand-off to the engine's control thread.
//
// Hosts call a plugin's parameter setter from their audio thread (LV2 run(), CLAP process()
// events, VST3 process() changes), but Engine::set may allocate and lock (a structural change
// builds a whole pipeline). So the audio thread only stores the value in an atomic and marks
// it changed (no allocation, lock or system call); a control thread (ControlThread) takes the
// marked values and calls Engine::set, which hands them back to the audio thread through the
// engine's own lock-free queue, where they glide (live) or crossfade in (structural).
//
// Values are doubles, as the table's; hosts speak float. A host value that rounds to the same
// float as the value held is no change, so a table default (1.45 ms) or a restored state's
// value survives a host that echoes it back as a float, bit for bit.
#pragma once

#include <array>
#include <atomic>

#include "tactus/params/params.hpp"

namespace tactus::plugin {

class HostParameters {
  public:
    HostParameters();  // the table's defaults, none marked

    // Any thread, real-time safe: a host's value (clamped, rounded for whole-number rows).
    void set_from_host(P id, float value) noexcept;
    // Any thread: an exact value (a restored state, a preset), marked for the control thread.
    void set_exact(P id, double value) noexcept;
    void set_all(const Settings& settings) noexcept;
    // Any thread: the value last asked for.
    double value(P id) const noexcept {
        return values_[static_cast<size_t>(id)].load(std::memory_order_acquire);
    }
    Settings settings() const noexcept;
    bool changed() const noexcept { return any_.load(std::memory_order_acquire); }

    // Control thread: calls apply(id, value) for every value marked since the last call.
    template <class Apply>
    void for_each_marked(Apply&& apply) {
        if (!any_.exchange(false, std::memory_order_acq_rel)) return;
        for (size_t i = 0; i < changed_.size(); ++i)
            if (changed_[i].exchange(false, std::memory_order_acq_rel))
                apply(static_cast<P>(i), values_[i].load(std::memory_order_acquire));
    }

  private:
    static constexpr size_t kCount = static_cast<size_t>(P::count);
    std::array<std::atomic<double>, kCount> values_;
    std::array<std::atomic<bool>, kCount> changed_;
    std::atomic<bool> any_{false};
};

static_assert(std::atomic<double>::is_always_lock_free);

}  // namespace tactus::plugin
