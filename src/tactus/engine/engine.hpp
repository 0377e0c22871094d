// The whole pipeline of paper Figure 4 as one real-time processor:
// audio -> analysis -> mapping -> synthesis -> post-processing -> vibration.
// Analysis runs at the input rate. Synthesis and post-processing run at an internal rate, the
// input rate divided by an integer, and an Upsampler brings the result back to the input rate.
// The vibration has nothing above the band's upper edge (<= 2 kHz), and synthesis samples one
// continuous-time signal (envelope and glides are exact at every sample instant, the phase
// integrates the glide exactly), so an internal rate of at least 11.025 kHz (5.5 times the
// highest edge) renders the same vibration as the input rate: eval/evaluate.py's pulse
// frequencies agree within 0.1 Hz at 44.1, 22.05 and 11.025 kHz. It costs a quarter of the input
// rate's synthesis and post-processing at 44.1 and 48 kHz. process() takes any block size and
// gives the same output for any split of the input.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "tactus/analysis/analyzer.hpp"
#include "tactus/params/params.hpp"
#include "tactus/engine/upsampler.hpp"
#include "tactus/mapping/mapper.hpp"
#include "tactus/post/post_chain.hpp"
#include "tactus/synthesis/voice.hpp"

namespace tactus {

// Receives every analysis frame and the control frame mapped from it, on the audio thread,
// inside process(): an implementation must itself be real-time safe when used live.
class FrameObserver {
  public:
    virtual ~FrameObserver() = default;
    virtual void on_frame(const Features& features, const ControlFrame& control) noexcept = 0;
    // The features on_frame() reads besides the onsets (all by default); the engine computes
    // only these and what the mapping reads.
    virtual FeatureSet reads() const noexcept { return {}; }
};

class Engine {
  public:
    static constexpr double kMinSampleRateHz = 8000;
    static constexpr double kMaxSampleRateHz = 192000;
    static constexpr int kMaxBlock = 4096;
    static constexpr double kMinInternalRateHz = 11025;

    explicit Engine(Settings settings = {}) : settings_(settings) { set_observer(nullptr); }
    // The actuator the output drives (compensation, max drive, and whether it holds an offset:
    // its `dc` replaces the actuator.dc setting, which gates the NPIII pressure); none by
    // default. Before prepare.
    void set_actuator(std::optional<ActuatorProfile> actuator);

    // May allocate. Throws as check_sample_rate() does, or for a block outside 1-kMaxBlock.
    void prepare(double sample_rate_hz, int max_block);
    // Throws std::invalid_argument for a sample rate outside 8-192 kHz.
    static void check_sample_rate(double sample_rate_hz);
    void reset() noexcept;
    // Mono in, mono vibration out (may alias). count <= max_block.
    void process(const float* in, float* out, int count) noexcept;
    // The limiter's look-ahead plus the upsampler's delay, in samples at the input rate. The
    // upsampler's delay is taken out of the look-ahead, so this stays close to
    // post.lookahead_ms.
    int latency() const;
    // Input samples per internal (synthesis and post-processing) sample.
    int rate_divisor() const { return upsampler_.factor(); }

    void set_observer(FrameObserver* observer);
    const Settings& settings() const { return settings_; }
    double sample_rate_hz() const { return sample_rate_hz_; }
    int hop_samples() const { return analyzer_.hop_samples(); }
    const PostChain& post() const { return post_; }
    // Output samples the final clip at the ceiling changed (it should not: the limiter leaves
    // a margin), post-processing's own clips included.
    int64_t clipped_samples() const { return post_.clipped_samples() + clipped_; }

  private:
    Settings settings_;
    std::optional<ActuatorProfile> actuator_;
    double sample_rate_hz_ = 0;
    Analyzer analyzer_;
    Mapper mapper_;
    Voice voice_;
    PostChain post_;
    Upsampler upsampler_;
    std::vector<float> internal_;  // synthesis and post-processing output below the input rate
    // One block of each low-frequency channel component, sized only when it is on.
    std::vector<float> flutter_, pressure_;
    int64_t position_ = 0;  // input samples consumed since reset
    float ceiling_ = 1.0f;
    int64_t clipped_ = 0;
    FrameObserver* observer_ = nullptr;
};

}  // namespace tactus
