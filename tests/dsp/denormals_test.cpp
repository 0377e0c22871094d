// ScopedFlushDenormals: inside its scope a product that would be denormal is 0 and a denormal
// input counts as 0; outside, and after it, arithmetic is IEEE again. Runs for real on arm64 and
// armhf under qemu-user (make test-arm); tests/dsp/denormals_aarch64.sh checks the instructions
// clang emits for aarch64 in every build.
#include "tactus/dsp/denormals.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace tactus {
namespace {

// Kept out of the optimiser's reach so the product is computed at run time.
float multiply(float a, float b) {
    volatile float x = a, y = b;
    return x * y;
}

TEST(ScopedFlushDenormals, FlushesInsideItsScopeOnly) {
    const float tiny = std::numeric_limits<float>::min();  // smallest normal
    const float denormal = tiny / 4;
    ASSERT_GT(multiply(tiny, 0.25f), 0.0f) << "the host does not compute denormals at all";
    {
        const ScopedFlushDenormals flush;
        EXPECT_EQ(multiply(tiny, 0.25f), 0.0f);     // result flushed
        EXPECT_EQ(multiply(denormal, 4.0f), 0.0f);  // input flushed
        {
            const ScopedFlushDenormals nested;
            EXPECT_EQ(multiply(tiny, 0.25f), 0.0f);
        }
        EXPECT_EQ(multiply(tiny, 0.25f), 0.0f);  // the outer scope still flushes
    }
    EXPECT_EQ(multiply(tiny, 0.25f), denormal);  // restored
    EXPECT_EQ(multiply(denormal, 4.0f), tiny);
}

}  // namespace
}  // namespace tactus
