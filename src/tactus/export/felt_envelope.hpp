// The vibration's envelope as the skin weighs it (docs/architecture.md, "Measuring quality and
// speed"): the peak of the rendered vibration over one period of its carrier, weighted by the P
// channel's sensitivity at the carrier frequency (the inverse of its threshold curve, 0 dB at
// 250 Hz: perception/threshold.hpp). The flattening filter boosts low carriers so that they are
// felt as strongly as 250 Hz; this undoes that boost to read what is felt, not the drive.
// Offline, on a 1 ms grid: the exports (ahap, haptic, Android) are drawn from it.
#pragma once

#include <cstdint>
#include <vector>

namespace tactus {

class FeltEnvelope {
  public:
    static constexpr double kStepS = 0.001;
    // The longest carrier period looked over: the P channel's lowest frequency (40 Hz).
    static constexpr double kMaxPeriodS = 0.025;

    explicit FeltEnvelope(double sample_rate_hz);
    // The next `count` samples of vibration (full scale 1), their carrier at `carrier_hz`.
    void write(const float* vibration, int count, double carrier_hz);
    // Felt amplitude (full scale 1 at 250 Hz) at every step so far; the last step may be partial.
    std::vector<double> felt() const;
    // Carrier frequency at every step (the last one written in it).
    const std::vector<double>& carrier_hz() const { return carrier_hz_; }
    // The P channel's sensitivity at f relative to 250 Hz, linear (1 at 250 Hz).
    static double weight(double frequency_hz);

  private:
    double sample_rate_hz_;
    int64_t samples_ = 0;
    std::vector<double> step_peak_, carrier_hz_;
};

}  // namespace tactus
