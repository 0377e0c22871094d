// Integer-factor interpolation from the engine's internal rate back to the output rate: a
// polyphase FIR (Crochiere & Rabiner 1983, ch. 3) with a minimum-phase Kaiser-windowed-sinc
// low-pass cut at the internal Nyquist frequency. The vibration has nothing above the band's
// upper edge (<= 2 kHz), far below that: the low-pass passes it (< 0.01 dB ripple) and removes
// the images around multiples of the internal rate (> 60 dB down when the internal rate is at
// least 5 times the edge). Minimum phase (homomorphic design, Oppenheim & Schafer 2010, §13.9):
// its delay is about 1.5 internal samples instead of the 4 of the linear-phase filter.
// Output sample m = q F + r depends only on internal samples up to q: process() is causal and
// gives the same output for any split of the stream.
#pragma once

#include <array>
#include <vector>

#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class Upsampler {
  public:
    static constexpr int kMaxFactor = 16;
    static constexpr int kTapsPerPhase = 8;

    // The internal side of `output` (rate, largest output block): its rate over `factor`, and
    // the most internal samples one process() call consumes.
    static ProcessSpec internal_spec(const ProcessSpec& output, int factor) {
        return {.sample_rate_hz = output.sample_rate_hz / factor,
                .max_block = (output.max_block + factor - 1) / factor + 1};
    }
    // spec: the output side; `factor` output samples per internal sample. May allocate
    // (design).
    void prepare(const ProcessSpec& spec, int factor);
    void reset() noexcept;
    // Consumes `internal_count` internal samples and writes `count` output samples: exactly
    // those whose time m satisfies floor(m / F) < samples consumed so far.
    void process(const float* internal, int internal_count, float* out, int count) noexcept;

    int factor() const { return factor_; }
    // Group delay at low frequencies, in output samples.
    double delay_samples() const { return delay_samples_; }
    int latency() const {
        // NOLINTNEXTLINE(bugprone-incorrect-roundings): >= 0; lround could move a rounding
        return static_cast<int>(delay_samples_ + 0.5);
    }

  private:
    int factor_ = 1, phase_ = 0;
    double delay_samples_ = 0;
    // taps_[i][r] = h[i F + r]: the F outputs after internal sample q are
    // sum_i x[q - i] taps_[i][0 ... F-1], one vector operation per tap.
    std::array<std::array<float, kMaxFactor>, kTapsPerPhase> taps_{};
    std::vector<float> line_;  // the last kTapsPerPhase internal samples, then the new ones
};

}  // namespace tactus
