#include "tactus/dsp/upsampler.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "tactus/core/vector_clones.hpp"
#include "tactus/dsp/upsampler_taps.hpp"

namespace tactus {
namespace {
using Taps = std::array<std::array<float, Upsampler::kMaxFactor>, Upsampler::kTapsPerPhase>;

// The outputs from phase r on, F a constant: the phase loop unrolls and vectorises (each output
// sums its taps in the same order as for any F). Returns the phase after the last output.
template <int F>
TACTUS_VECTOR_CLONES int run(const Taps& taps, const float* x, int r, float* out,
                             int count) noexcept {
    if constexpr (F < 2) {
        return 0;  // factor 1 copies (process())
    } else {
        for (int done = 0; done < count; ++x) {
            std::array<float, F> y{};
            for (int i = 0; i < Upsampler::kTapsPerPhase; ++i) {
                const float xi = x[-i];
                for (int p = 0; p < F; ++p) y[p] += xi * taps[i][p];
            }
            if (r == 0 && count - done >= F) {  // all F outputs: a fixed-size copy, no memcpy call
                std::copy_n(y.data(), F, out + done);
                done += F;
                continue;
            }
            const int n = std::min(F - r, count - done);
            std::copy_n(y.data() + r, n, out + done);
            done += n;
            r = (r + n) % F;
        }
        return r;
    }
}

template <int... F>
constexpr auto run_table(std::integer_sequence<int, F...>) {
    return std::array{&run<F>...};
}
}  // namespace
void Upsampler::prepare(const ProcessSpec& spec, int factor) {
    if (factor < 1 || factor > kMaxFactor)
        throw std::invalid_argument("upsampling factor must be 1-16");
    factor_ = factor;
    taps_ = {};
    delay_samples_ = 0.0;
    if (factor > 1) {  // factor 1 copies: no filter; the others designed at build time
        const UpsamplerTaps& t = upsampler_taps_table(factor);
        taps_ = t.taps;
        delay_samples_ = t.delay_samples;
    }
    line_.assign(size_t{kTapsPerPhase} + static_cast<size_t>(internal_spec(spec, factor).max_block),
                 0.0f);
    reset();
}

void Upsampler::reset() noexcept {
    std::fill(line_.begin(), line_.end(), 0.0f);
    phase_ = 0;
}

void Upsampler::process(const float* internal, int internal_count, float* out, int count) noexcept {
    constexpr int K = kTapsPerPhase;
    if (factor_ == 1) {
        std::copy_n(internal, count, out);
        return;
    }
    std::copy_n(internal, internal_count, line_.data() + K);
    // line_[K - 1 + j] is the j-th internal sample at or after the first output's time.
    const float* x = line_.data() + K - (phase_ != 0 ? 1 : 0);
    static constexpr auto kRuns = run_table(std::make_integer_sequence<int, kMaxFactor + 1>{});
    phase_ = kRuns[static_cast<size_t>(factor_)](taps_, x, phase_, out, count);
    std::copy_n(line_.data() + internal_count, K, line_.data());
}

}  // namespace tactus
