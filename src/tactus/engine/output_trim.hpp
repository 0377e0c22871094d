// What each actuator output adds to its chain's signal: a trim gain (live, gliding over
// kGainGlideMs, after the limiter: it can only lower the level, so the ceiling holds) and an
// alignment delay (structural), e.g. to line up actuators at different distances from the
// sound, or with a sound path that has its own latency.
#pragma once

#include <optional>

#include "tactus/actuator/profile.hpp"
#include "tactus/dsp/delay_line.hpp"
#include "tactus/dsp/process_spec.hpp"
#include "tactus/engine/route.hpp"

namespace tactus {

// What an actuator output is given (control thread, before prepare).
struct ActuatorOutput {
    std::optional<ActuatorProfile> profile;  // none: no compensation, the ceiling of the settings
    double gain_db = 0;                      // trim after the limiter, kMinGainDb ... 0 (live)
    double delay_ms = 0;                     // alignment, 0 ... kMaxDelayMs (structural)
    Route route{};                           // what it plays (structural)
    Overlay overlay{};                       // its own mapping values (structural)

    bool operator==(const ActuatorOutput&) const = default;

    static constexpr double kMinGainDb = -60;
    static constexpr double kMaxDelayMs = 1000;
    // Throws std::invalid_argument naming the actuator index and the value.
    void check(int index) const;
    // Whether the input of `spec` has what the route takes (a channel of several, a band below
    // Nyquist); throws std::invalid_argument naming the actuator index and the route.
    void check_input(int index, const ProcessSpec& spec) const;
    // Throws std::invalid_argument naming the gain (any thread).
    static void check_gain_db(double gain_db);
};

class OutputTrim {
  public:
    static constexpr double kGainGlideMs = 20;

    void prepare(const ProcessSpec& spec, const ActuatorOutput& output);  // may allocate
    void reset() noexcept;
    void set_gain_db(double gain_db) noexcept;  // audio thread
    void process(float* samples, int count) noexcept;
    int latency() const { return delay_.delay_samples(); }  // the delay

  private:
    double gain_ = 1, gain_target_ = 1, gain_step_ = 0;
    int gain_left_ = 0, glide_samples_ = 1;
    DelayLine delay_;  // one channel, latency() samples
};

}  // namespace tactus
