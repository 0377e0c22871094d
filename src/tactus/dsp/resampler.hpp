// Streaming sample-rate conversion: a polyphase FIR whose taps sample one continuous-time
// kernel, so the output is the same band-limited signal at every input rate (the analysis reads
// it, reduced to a fixed rate: engine.hpp, "Rates"). The kernel is a Kaiser-windowed sinc
// (Band::analysis: pass band to kPassEdge, stop band from kStopEdge of the output rate,
// kStopBandDb down; Kaiser 1974, Oppenheim & Schafer 7.6) made minimum phase by the folded real
// cepstrum (Oppenheim & Schafer 13.9.2): causal and front-loaded, it delays onsets by a fraction
// of a millisecond where the linear-phase kernel would delay them by half its length.
// Band::listening is for sound someone hears (`tactus live` plays a file at the device's rate):
// a wider pass band, kListening* of the lower of the two rates, either way.
//
// Output sample n stands at input sample position n * M / L (L / M the output / input rate ratio
// in lowest terms, L <= kMaxPhases) and reads input up to index floor(n * M / L): constant
// latency, exact positions. Setup thread: prepare(); audio thread: reset() and process(),
// which never allocate.
#pragma once

#include <cstdint>
#include <vector>

namespace tactus {

class Resampler {
  public:
    static constexpr double kPassEdge = 0.35;  // of the output rate: 5.6 kHz at 16 kHz
    static constexpr double kStopEdge = 0.45;  // 7.2 kHz: above it, less than the input rates share
    static constexpr double kStopBandDb = 60;  // Kaiser design attenuation
    static constexpr int kMaxPhases = 1024;    // L at most; other ratios are approximated
    static constexpr double kListeningPassEdge = 0.45;  // of the lower rate: 19.8 kHz at 44.1 kHz
    static constexpr double kListeningStopEdge = 0.5;   // its Nyquist frequency
    static constexpr double kListeningStopBandDb = 90;  // below 16-bit quantisation
    enum class Band { analysis, listening };

    struct Ratio {
        int64_t up = 1, down = 1;  // L, M
    };
    // The ratio prepare() uses for these rates (see below).
    static Ratio ratio_for(double input_rate_hz, double output_rate_hz);

    // Allocates. Band::analysis reduces the rate (output_rate_hz <= input_rate_hz);
    // Band::listening converts either way. The output rate is exactly input_rate_hz * L / M:
    // output_rate_hz itself when the ratio reduces to L <= kMaxPhases, else within
    // 1 / (2 kMaxPhases) of it. `max_block`: input samples per process() call.
    void prepare(double input_rate_hz, double output_rate_hz, int max_block,
                 Band band = Band::analysis);
    void reset() noexcept;

    double output_rate_hz() const { return output_rate_hz_; }
    int64_t up() const { return up_; }      // L
    int64_t down() const { return down_; }  // M
    // Input samples that must have been written for output n to exist: floor(n M / L) + 1.
    int64_t inputs_for(int64_t n) const { return n * down_ / up_ + 1; }
    // The delay of the kernel's energy centroid, in output samples: an onset in the input at
    // position p shows in the output near p * L / M + delay_output_samples().
    double delay_output_samples() const { return delay_output_samples_; }
    int64_t outputs_written() const { return next_output_; }
    // Input samples each output reads (the kernel's span, padded to a multiple of 8).
    int taps() const { return taps_; }

    // count <= max_block input samples in; returns the output samples written to `out`: at most
    // count reducing the rate, at most count * L / M + 1 raising it.
    int process(const float* in, int count, float* out) noexcept;

  private:
    int64_t up_ = 1, down_ = 1;
    int taps_ = 1;                // per phase
    std::vector<float> kernel_;   // up_ phases of taps_, oldest input first
    std::vector<float> history_;  // taps_ - 1 past inputs, then one block
    int64_t next_output_ = 0;     // index of the next output sample
    int64_t next_base_ = 0;       // floor(next_output_ * M / L): its newest input
    int64_t phase_ = 0;           // (next_output_ * M) mod L
    int64_t written_ = 0;         // input samples taken since reset
    double output_rate_hz_ = 0, delay_output_samples_ = 0;
};

}  // namespace tactus
