// Band-limit to the vibrotactile range (paper §6, first and last post-processing stages):
// Butterworth high-pass at low_hz and low-pass at high_hz, each of the given even order.
#pragma once

#include <array>

#include "tactus/dsp/biquad.hpp"

namespace tactus {

class BandLimit {
  public:
    static constexpr int kMaxOrder = 8;

    void prepare(double sample_rate_hz, double low_hz, double high_hz, int order);
    void reset() noexcept;
    void process(float* samples, int count) noexcept;
    double magnitude_db(double frequency_hz) const;

  private:
    std::array<Biquad, kMaxOrder> sections_;  // order/2 high-pass then order/2 low-pass
    int count_ = 0;
    double sample_rate_hz_ = 48000;
};

}  // namespace tactus
