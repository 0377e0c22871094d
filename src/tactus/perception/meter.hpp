// Sensation-level meter: which channels of touch a vibration signal engages, and how strongly,
// over time (paper §3.5 and §5; docs/perception.md).
// The signal (full scale 1) becomes skin displacement through an actuator calibration, um peak
// per full-scale sine vs frequency (0 where the actuator cannot move, e.g. DC without DC
// capability). Each channel is one detector integrating stimulus energy across its frequencies
// [P: paper §5.1 and its reference [2]; assumed for NP channels]: a short-time spectrum
// (Hann window, 8 frames per window) is weighted per bin by (displacement / threshold)^2, the
// channel's threshold curve at the contact area (threshold.hpp, 1 s curve), and summed, so a
// steady sine of peak displacement A reads 20 log10 A - T_c(f). P integrates energy over 1 s
// (temporal summation, -3 dB per doubling of duration up to ~1 s: Verrillo 1965 [recalled],
// Gescheider 1976): its frame values are averaged over the last second, so a burst of d < 1 s
// reads 10 log10(d / 1 s) lower, which is P's duration law (applied in full at every frequency
// and contact area, where threshold.hpp weakens it below 80 Hz and for small contacts), and the
// reading never exceeds the current frame's own value: summation lowers the threshold of longer
// stimuli, it does not make a sensation outlast its stimulus. NP channels do not sum over time
// and read their window alone (bursts shorter than ~3/8 of the window read low). Windows resolve
// each channel's lowest frequencies: 0.16 s (P, from 40 Hz: 6.25 Hz bins), 0.4 s (NPI: 2.5 Hz
// bins), 0.08 s (NPII, from 100 Hz), 5.12 s (NPIII, from 0.4 Hz). The channels read the signal
// reduced to kRateHz (dsp/resampler.hpp, its analysis band: flat to 2.8 kHz, where every
// channel's threshold lies 29 dB and more above its best and vibration output ends; 1 kHz at
// the latest, post.band_high_hz), so each window's transform is 5.5 times shorter at 44.1 kHz.
// Readings are causal, every 10 ms; a static offset reads 3 dB high (its peak equals its RMS).
// Sensation levels are dB SL, 0 = below threshold (not engaged); the combined column is
// perception::combined_sensation_db (Hollins & Roy 1996).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "tactus/dsp/resampler.hpp"
#include "tactus/dsp/sample_history.hpp"
#include "tactus/perception/sensation.hpp"

namespace tactus {
class RealFft;
}

namespace tactus::perception {

struct MeterReading {
    double time_s = 0;         // end of the interval the reading covers
    ChannelLevels level_db{};  // per channel, dB SL (0: not engaged)
    double combined_db = 0;    // combined perceived intensity, dB SL
};

class SensationMeter {
  public:
    static constexpr double kStepS = 0.01;
    static constexpr double kRateHz = 8000;        // signals at higher rates are reduced to it
    static constexpr double kPIntegrationS = 1.0;  // P temporal summation up to ~1 s
    // Each channel's hop, in 10 ms steps; its window is kHopsPerWindow hops.
    static constexpr std::array<int, 4> kHopSteps = {2, 5, 1, 64};  // P, NPI, NPII, NPIII
    static constexpr int kHopsPerWindow = 8;

    using Calibration = std::function<double(double frequency_hz)>;  // um peak per full scale
    // The channels a meter computes (by Channel); the others read 0 and are left out of
    // combined_db. Meters of disjoint channels fed the same samples read, channel for channel,
    // what one meter of them all reads, bit for bit: their work can go to threads of their own.
    using Channels = std::array<bool, 4>;
    static constexpr Channels kAllChannels = {true, true, true, true};

    SensationMeter();
    ~SensationMeter();
    // May allocate.
    void prepare(double input_rate_hz, const Calibration& displacement_um, double contact_area_cm2,
                 const Channels& channels = kAllChannels);
    // Feeds samples; calls on_reading for every 10 ms step completed. Not real-time safe
    // (callback), but allocation-free after prepare().
    void write(const float* samples, int count,
               const std::function<void(const MeterReading&)>& on_reading);
    // Feeds silence for the longest P/NPI window so the last events are fully counted.
    void finish(const std::function<void(const MeterReading&)>& on_reading);

  private:
    struct ChannelState;
    // Meters samples at the meter's rate (reduced, or the input's own).
    void meter(const float* samples, int count,
               const std::function<void(const MeterReading&)>& on_reading);
    void step(const std::function<void(const MeterReading&)>& on_reading);

    static constexpr int kChunk = 1024;       // input samples cleaned and reduced at a time
    double input_rate_hz_ = 0, rate_hz_ = 0;  // the input's and the meter's
    bool reduced() const { return rate_hz_ < input_rate_hz_; }  // through resampler_
    Resampler resampler_;
    int delay_left_ = 0;  // its first outputs, dropped: the readings keep the input's timing
    int step_samples_ = 0, filled_ = 0;           // at the meter's rate
    int64_t steps_ = 0, written_ = 0;             // readings given, input samples taken
    SampleHistory history_;                       // the longest window
    std::vector<float> clean_, reduced_samples_;  // a chunk of input, non-finite samples as 0
    std::vector<std::unique_ptr<ChannelState>> channels_;
};

// Per-channel summary of a run of readings.
struct ChannelSummary {
    double max_db = 0;             // largest sensation level
    double engaged_fraction = 0;   // fraction of readings above threshold
    double median_engaged_db = 0;  // median sensation level while engaged (0 if never)
};
struct MeterSummary {
    std::array<ChannelSummary, 4> channels;
    ChannelSummary combined;
    int64_t readings = 0;
};
class MeterSummariser {
  public:
    void add(const MeterReading& r);
    MeterSummary summary() const;

  private:
    std::array<std::vector<double>, 5> levels_;  // four channels, combined
};

}  // namespace tactus::perception
