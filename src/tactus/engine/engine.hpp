// The whole pipeline of paper Figure 4 as one real-time processor:
// audio -> analysis -> mapping -> synthesis -> post-processing -> vibration.
// process() takes any block size and gives the same output for any split of the input.
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "tactus/analysis/analyzer.hpp"
#include "tactus/core/params.hpp"
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
};

class Engine {
  public:
    static constexpr double kMinSampleRateHz = 8000;
    static constexpr double kMaxSampleRateHz = 192000;
    static constexpr int kMaxBlock = 4096;

    explicit Engine(Settings settings = {}) : settings_(settings) {}
    // The actuator the output drives (compensation, max drive, and whether it holds an offset:
    // its `dc` replaces the actuator.dc setting, which gates the NPIII pressure); none by
    // default. Before prepare.
    void set_actuator(std::optional<ActuatorProfile> actuator);

    // May allocate. Throws std::invalid_argument for a sample rate outside 8-192 kHz.
    void prepare(double sample_rate_hz, int max_block);
    void reset() noexcept;
    // Mono in, mono vibration out (may alias). count <= max_block.
    void process(const float* in, float* out, int count) noexcept;
    int latency() const { return post_.latency_samples(); }

    void set_observer(FrameObserver* observer) { observer_ = observer; }
    const Settings& settings() const { return settings_; }
    double sample_rate_hz() const { return sample_rate_hz_; }
    int hop_samples() const { return analyzer_.hop_samples(); }
    const PostChain& post() const { return post_; }

  private:
    Settings settings_;
    std::optional<ActuatorProfile> actuator_;
    double sample_rate_hz_ = 0;
    Analyzer analyzer_;
    Mapper mapper_;
    Voice voice_;
    PostChain post_;
    // One block of each low-frequency channel component, sized only when it is on.
    std::vector<float> flutter_, pressure_;
    FrameObserver* observer_ = nullptr;
};

}  // namespace tactus
