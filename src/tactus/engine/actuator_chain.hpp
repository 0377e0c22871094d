// The post-processing chain for one actuator profile (compensation, ceiling) and the upsampler
// back to the input rate. Every chain reads the one synthesised vibration (paper §6: one signal
// for every tonehole), so N actuators share one analysis, mapping and synthesis, and actuators
// with the same profile share one chain (their OutputTrim differs).
#pragma once

#include <cstdint>
#include <vector>

#include "tactus/actuator/profile.hpp"
#include "tactus/dsp/upsampler.hpp"
#include "tactus/params/params.hpp"
#include "tactus/post/post_chain.hpp"

namespace tactus {

class ActuatorChain {
  public:
    // spec: the output (input-rate) side; synthesis and post-processing run at
    // spec.sample_rate_hz / rate_divisor. May allocate. `profile` may be null (no compensation).
    void prepare(const ProcessSpec& spec, int rate_divisor, const Settings& settings,
                 const ActuatorProfile* profile);
    void reset() noexcept;
    // Audio thread: the live settings over `glide_samples` internal samples.
    void set_live(const Settings& settings, int glide_samples) noexcept;
    // The ceiling the mapper's pressure is a fraction of (the first chain's): this chain scales
    // the pressure to its own.
    void set_pressure_reference(double ceiling) noexcept {
        pressure_scale_ = post_.ceiling() / ceiling;
    }
    PostChain& post() { return post_; }
    const PostChain& post() const { return post_; }

    // Audio thread. carrier, flutter (may be null), pressure (may be null): `internal_count`
    // internal samples; carrier and flutter are used as scratch when `in_place`, else copied.
    // Writes `count` samples at the input rate to out.
    void process(float* carrier, float* flutter, const float* pressure, int internal_count,
                 bool in_place, float* out, int count) noexcept;

    int64_t clipped_samples() const { return post_.clipped_samples() + clipped_; }
    const Upsampler& upsampler() const { return upsampler_; }
    // The look-ahead and the upsampler's delay, in output samples.
    int latency() const { return post_.latency() * upsampler_.factor() + upsampler_.latency(); }

  private:
    PostChain post_;
    Upsampler upsampler_;
    std::vector<float> carrier_, flutter_, pressure_;  // this chain's copies
    double pressure_scale_ = 1;                        // this ceiling over the reference ceiling
    float ceiling_ = 1, clip_ceiling_ = 1;             // clip_ceiling_: the higher during a glide
    int64_t clipped_ = 0;
};

}  // namespace tactus
