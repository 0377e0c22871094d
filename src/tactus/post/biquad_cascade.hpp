// A cascade of biquads run over a block, sample by sample through every section, with the
// sections copied into locals of a size fixed at compile time: the compiler unrolls the
// section loop and keeps the filter states in registers instead of storing and reloading them
// every sample. The arithmetic, and so the output, is exactly that of Biquad::process in turn.
#pragma once

#include <array>
#include <utility>

#include "tactus/post/biquad.hpp"

namespace tactus {

namespace detail {
template <int N>
void run_cascade(Biquad* sections, float* samples, int count, double gain) noexcept {
    std::array<Biquad, N> local;
    for (int s = 0; s < N; ++s) local[s] = sections[s];
    for (int i = 0; i < count; ++i) {
        double x = samples[i] * gain;
        for (int s = 0; s < N; ++s) x = local[s].process(x);
        samples[i] = static_cast<float>(x);
    }
    for (int s = 0; s < N; ++s) sections[s] = local[s];
}

template <int... N>
constexpr auto cascade_table(std::integer_sequence<int, N...>) {
    return std::array{&run_cascade<N>...};
}
}  // namespace detail

// samples[i] = the first `size` sections in turn applied to gain * samples[i]; size <= 16.
inline void process_cascade(Biquad* sections, int size, float* samples, int count,
                            double gain = 1.0) noexcept {
    static constexpr auto kTable = detail::cascade_table(std::make_integer_sequence<int, 17>{});
    kTable[static_cast<size_t>(size)](sections, samples, count, gain);
}

}  // namespace tactus
