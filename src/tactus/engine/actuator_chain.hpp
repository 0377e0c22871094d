// The post-processing chain for one actuator profile (compensation, ceiling) and the upsampler
// back to the input rate. Every chain reads the one synthesised vibration (paper §6: one signal
// for every tonehole), so N actuators share one analysis, mapping and synthesis, and actuators
// with the same profile share one chain (their OutputTrim differs).
#pragma once

#include <cstdint>
#include <vector>

#include "tactus/actuator/profile.hpp"
#include "tactus/engine/upsampler.hpp"
#include "tactus/params/params.hpp"
#include "tactus/post/post_chain.hpp"

namespace tactus {

// The sizes and rates a chain is prepared for, by name.
struct ChainSpec {
    double internal_rate_hz = 48000;  // synthesis and post-processing
    int rate_divisor = 1;             // input samples per internal sample
    int max_internal_block = 1;       // internal samples one process() call gets at most
    int max_block = 1;                // output samples one process() call writes at most
};

class ActuatorChain {
  public:
    // May allocate. `profile` may be null (no compensation).
    void prepare(const ChainSpec& chain, const Settings& settings,
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

  private:
    PostChain post_;
    Upsampler upsampler_;
    std::vector<float> carrier_, flutter_, pressure_;  // this chain's copies
    double pressure_scale_ = 1;  // this ceiling over the reference ceiling
    float ceiling_ = 1, clip_ceiling_ = 1;  // clip_ceiling_: the higher during a glide
    int64_t clipped_ = 0;
};

}  // namespace tactus
