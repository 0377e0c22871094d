#include "tactus/dsp/resampler.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "tactus/core/vector_clones.hpp"
#include "tactus/dsp/resampler_kernel.hpp"

namespace tactus {
namespace {

constexpr int kLanes = 8;  // taps padded to a multiple: the dot product vectorises

// The kernel at `t` samples (of the lower rate) after its start (0 outside it), linearly
// interpolated.
double kernel_at(const ResamplerKernelView& k, double t) {
    const double x = t * k.points_per_unit;
    if (x < 0) return 0;
    const auto i = static_cast<size_t>(x);
    if (i + 1 >= k.points.size()) return 0;
    const double f = x - static_cast<double>(i);
    return k.points[i] + f * (k.points[i + 1] - k.points[i]);
}

bool whole(double x) {
    return x == std::floor(x) && x < 1e12;
}

}  // namespace

Resampler::Ratio Resampler::ratio_for(double input_rate_hz, double output_rate_hz) {
    Ratio r{kMaxPhases + 1, 1};
    if (whole(input_rate_hz) && whole(output_rate_hz)) {
        const auto in = static_cast<int64_t>(input_rate_hz);
        const auto out = static_cast<int64_t>(output_rate_hz);
        const int64_t g = std::gcd(in, out);
        r = {out / g, in / g};
    }
    if (r.up > kMaxPhases) {  // the nearest ratio with L = kMaxPhases
        r.up = kMaxPhases;
        r.down = std::max<int64_t>(1, std::llround(input_rate_hz / output_rate_hz * kMaxPhases));
        const int64_t g = std::gcd(r.up, r.down);
        r.up /= g;
        r.down /= g;
    }
    return r;
}

void Resampler::prepare(double input_rate_hz, double output_rate_hz, int max_block, Band band) {
    if (!(output_rate_hz > 0 && (output_rate_hz <= input_rate_hz || band == Band::listening)))
        throw std::invalid_argument("resampler: the output rate must be in (0, input rate]");
    const Ratio r = ratio_for(input_rate_hz, output_rate_hz);
    up_ = r.up;
    down_ = r.down;
    output_rate_hz_ = input_rate_hz * static_cast<double>(up_) / static_cast<double>(down_);
    const ResamplerKernelView k = resampler_kernel_table(band);  // designed at build time
    // Input samples per output sample: down / up. Tap i reads the input i samples before the
    // newest, at (phase / up + i) input samples = (phase / up + i) up / down output samples;
    // the kernel's unit is a sample of the lower rate: the output's, unless the rate rises.
    const double outputs_per_input = static_cast<double>(up_) / static_cast<double>(down_);
    const double units_per_input = std::min(1.0, outputs_per_input);
    delay_output_samples_ = k.delay_output_samples * outputs_per_input / units_per_input;
    const double span = static_cast<double>(k.points.size()) / k.points_per_unit;  // units
    const int needed = static_cast<int>(std::ceil(span / units_per_input)) + 1;
    taps_ = (needed + kLanes - 1) / kLanes * kLanes;
    kernel_.assign(static_cast<size_t>(up_ * taps_), 0.0f);
    for (int64_t p = 0; p < up_; ++p) {
        float* phase = kernel_.data() + p * taps_;
        double sum = 0;
        for (int i = 0; i < taps_; ++i) {
            const double t =
                (static_cast<double>(p) / static_cast<double>(up_) + i) * units_per_input;
            sum += phase[taps_ - 1 - i] = static_cast<float>(kernel_at(k, t) * units_per_input);
        }
        for (int i = 0; i < taps_; ++i) phase[i] = static_cast<float>(phase[i] / sum);  // DC: 1
    }
    history_.assign(static_cast<size_t>(taps_) - 1 + static_cast<size_t>(max_block), 0.0f);
    reset();
}

void Resampler::reset() noexcept {
    std::fill(history_.begin(), history_.end(), 0.0f);
    next_output_ = next_base_ = phase_ = written_ = 0;
}

TACTUS_VECTOR_CLONES int Resampler::process(const float* in, int count, float* out) noexcept {
    const int taps = taps_;
    float* const history = history_.data();
    std::copy_n(in, count, history + taps - 1);
    const int64_t end = written_ + count;
    int produced = 0;
    while (next_base_ < end) {
        const float* x = history + (next_base_ - written_);  // taps samples, newest last
        const float* w = kernel_.data() + phase_ * taps;
        float s[kLanes] = {};
        // On x86-64 four vectors a step: fewer of the loop's own instructions, each lane's sum in
        // its order. GCC for Arm vectorises the loop better as written (a 64-frame block under
        // qemu, bench/arm_instructions.sh: arm64 44,913 instructions as written, 48,002 unrolled).
#if defined(__x86_64__)
#pragma GCC unroll 4
#endif
        for (int i = 0; i < taps; i += kLanes)
            for (int j = 0; j < kLanes; ++j) s[j] += w[i + j] * x[i + j];
        out[produced++] = ((s[0] + s[1]) + (s[2] + s[3])) + ((s[4] + s[5]) + (s[6] + s[7]));
        // An integer ratio (48 to 16 kHz) has one phase: no 64-bit division, which armhf makes
        // a library call (2 % of its 64-frame block, bench/arm_instructions.sh).
        if (up_ == 1) {
            next_base_ += down_;
        } else {
            phase_ += down_;
            next_base_ += phase_ / up_;
            phase_ %= up_;
        }
        ++next_output_;
    }
    std::copy(history + count, history + count + taps - 1, history);
    written_ = end;
    return produced;
}

}  // namespace tactus
