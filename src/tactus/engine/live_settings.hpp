// The settings the audio thread runs with while a control thread changes them (live parameters:
// docs/architecture.md, "Threads and queues"). Each live value glides linearly to what was last
// asked for over its parameter's smoothing time (ParamSpec::smoothing_ms), one step per analysis
// frame: the stages re-derive their coefficients from now() at each step, and the voice's and
// limiter's own per-sample glides smooth what lies between. A value with no smoothing time
// applies at once; a toggle with one glides through the values between off (0) and on (1), which
// the stage reads as a mix.
// Audio thread only; never allocates.
#pragma once

#include <array>
#include <utility>

#include "tactus/params/params.hpp"

namespace tactus {

class LiveSettings {
  public:
    static constexpr int kCount = static_cast<int>(P::count);

    // current = asked = `settings`. frames_per_second: the analysis frame rate.
    void prepare(const Settings& settings, double frames_per_second) noexcept;
    // Asks for `value` (already validated by Settings::set on the control thread).
    void ask(P id, double value) noexcept;
    // One analysis frame on; true when a gliding value moved.
    bool step() noexcept;
    // True (once) when an ask() applied at once since the last call.
    bool take_changed() noexcept { return std::exchange(changed_, false); }
    bool gliding() const noexcept { return gliding_count_ > 0; }
    const Settings& now() const noexcept { return now_; }

  private:
    Settings now_;
    double frames_per_second_ = 1;
    std::array<double, kCount> target_{}, step_{};
    std::array<int, kCount> frames_left_{};
    std::array<P, kCount> gliding_{};  // the ids with frames_left_ > 0
    int gliding_count_ = 0;
    bool changed_ = false;
};

}  // namespace tactus
