// Short-window K-weighted loudness in dB (LKFS scale): the ITU-R BS.1770-4 K-weighting
// (analysis/k_weighting.hpp), mean square (a running sum) over a short window instead of
// BS.1770's 400 ms, so that drum hits register within milliseconds. A full-scale 997 Hz sine
// reads -3.01 dB; doubling amplitude adds 6.02 dB. Several channels come as their K-weighted
// power, summed over the channels as BS.1770 sums them (engine/channel_power.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include "tactus/analysis/k_weighting.hpp"
#include "tactus/dsp/process_spec.hpp"

namespace tactus {

class Loudness {
  public:
    static constexpr double kFloorDb = -120.0;  // reported for silence

    void prepare(const ProcessSpec& spec, double window_ms);  // may allocate
    void reset() noexcept;
    void process(const float* samples, int count) noexcept;  // K-weights and stores squares
    // Instead of process(): the K-weighted power of each sample, summed over the channels.
    void process_power(const float* power, int count) noexcept;
    double loudness_db() const noexcept { return db_of(mean_square()); }  // the newest window's
    double mean_square() const noexcept;               // K-weighted, over the newest window
    static double db_of(double mean_square) noexcept;  // LKFS scale

    // process() for a caller that runs a copy of the K-weighting (filters()) in one wavefront
    // with other filters (Analyzer's CascadeLanes): open(), take() the square of each K-weighted
    // sample in order, close().
    struct Squares {
        double* ring;  // squares_
        size_t length, position;
        double sum, fresh;
        void take(double square) noexcept {
            sum += square - ring[position];
            ring[position] = square;
            fresh += square;
            if (++position == length) {  // re-sum once per window: no rounding drift
                position = 0;
                sum = fresh;
                fresh = 0.0;
            }
        }
    };
    Squares open() noexcept {
        return {squares_.data(), squares_.size(), position_, sum_, fresh_sum_};
    }
    void close(const Squares& squares) noexcept;
    // The K-weighting, KWeighting::kSections biquads in turn.
    const Biquad* filters() const noexcept { return k_weighting_.filters(); }

  private:
    KWeighting k_weighting_;
    std::vector<double> squares_;  // ring of K-weighted squares, one window long
    size_t position_ = 0;
    double sum_ = 0.0;  // of squares_, kept running
    // squares_[0 ... position_) summed in order as they are written: at the end of the ring it
    // is the exact re-sum that ends the drift, without a pass over the window in one sample.
    double fresh_sum_ = 0.0;
};

}  // namespace tactus
