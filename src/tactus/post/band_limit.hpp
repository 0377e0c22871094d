// Band-limit to the vibrotactile range (paper §6, first and last post-processing stages):
// Butterworth high-pass at low_hz and low-pass at high_hz, each of the given even order, or the
// high-pass alone for a signal that has nothing above high_hz.
#pragma once

#include <array>

#include "tactus/dsp/biquad.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

// The band passed: Butterworth slopes of `order` (2, 4, 6 or 8) at each edge.
struct BandEdges {
    double low_hz = 20;
    double high_hz = 1000;
    int order = 8;
    bool low_pass = true;  // false: the high-pass alone
};

class BandLimit {
  public:
    static constexpr int kMaxOrder = 8;

    void prepare(const ProcessSpec& spec, const BandEdges& band);
    int latency() const { return 0; }
    void reset() noexcept;
    void process(float* samples, int count) noexcept;
    double magnitude_db(double frequency_hz) const;

  private:
    std::array<Biquad, kMaxOrder> sections_;  // order/2 high-pass then order/2 low-pass
    int count_ = 0;
    double sample_rate_hz_ = 48000;
};

}  // namespace tactus
