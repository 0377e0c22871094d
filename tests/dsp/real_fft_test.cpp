// RealFft: a cosine on bin k reads N/2 there and ~0 elsewhere; inverse(forward(x)) = N x; sizes;
// the build's FFTW wisdom.
#include "tactus/dsp/real_fft.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "support/signals.hpp"
#include "tactus/dsp/fft_wisdom.hpp"

namespace tactus {
namespace {

TEST(RealFft, CosineOnABinAndRoundTrip) {
    for (int n : {64, 512, 4096}) {
        RealFft fft;
        fft.prepare(n);
        ASSERT_EQ(fft.size(), n);
        ASSERT_EQ(fft.bins(), n / 2 + 1);
        const int k0 = n / 8 + 3;
        for (int i = 0; i < n; ++i)
            fft.time()[i] = static_cast<float>(std::cos(2 * test::kTestPi * k0 * i / n));
        fft.forward();
        for (int k = 0; k < fft.bins(); ++k) {
            const double expected = k == k0 ? n / 2.0 : 0.0;
            ASSERT_NEAR(std::abs(fft.spectrum()[k]), expected, 1e-3 * n) << "n " << n << " k " << k;
        }
        const std::vector<float> x = test::white_noise(static_cast<size_t>(n), 9);
        std::copy(x.begin(), x.end(), fft.time());
        fft.forward();
        fft.inverse();
        for (int i = 0; i < n; ++i) ASSERT_NEAR(fft.time()[i] / n, x[i], 1e-5) << i;
    }
}

TEST(RealFft, PrepareAgainChangesSize) {
    RealFft fft;
    fft.prepare(256);
    fft.prepare(256);
    fft.prepare(1024);
    EXPECT_EQ(fft.size(), 1024);
    EXPECT_EQ(fft.bins(), 513);
}

// Prepared together (one wisdom import for the new sizes, planned at plan()): a size new to the
// process, one planned before, one prepared twice and one destroyed before plan() transform as
// RealFfts prepared alone do, bit for bit; after the PlanTogether, prepare() plans at once again.
TEST(RealFft, PreparedTogetherTransformAsPreparedAlone) {
    constexpr int kNew = 2700, kKnown = 512, kTwice = 1944;  // 2700, 1944: planned nowhere else
    RealFft known_alone;
    known_alone.prepare(kKnown);
    RealFft fresh, known, twice;
    {
        RealFft::PlanTogether together;
        fresh.prepare(kNew);
        known.prepare(kKnown);
        twice.prepare(kNew);
        twice.prepare(kTwice);
        {
            RealFft gone;
            gone.prepare(2400);
        }
        together.plan();
    }
    RealFft fresh_alone, twice_alone;
    fresh_alone.prepare(kNew);
    twice_alone.prepare(kTwice);
    for (auto [a, b] : {std::pair{&fresh, &fresh_alone}, std::pair{&known, &known_alone},
                        std::pair{&twice, &twice_alone}}) {
        const int n = a->size();
        ASSERT_EQ(b->size(), n);
        const std::vector<float> x = test::white_noise(static_cast<size_t>(n), 3);
        std::copy(x.begin(), x.end(), a->time());
        std::copy(x.begin(), x.end(), b->time());
        a->forward();
        b->forward();
        for (int k = 0; k < a->bins(); ++k) ASSERT_EQ(a->spectrum()[k], b->spectrum()[k]) << n;
        a->inverse();
        b->inverse();
        for (int i = 0; i < n; ++i) ASSERT_EQ(a->time()[i], b->time()[i]) << n;
    }
}

}  // namespace
}  // namespace tactus

namespace tactus {
namespace {

// The plan FFTW makes for a size (FFTW_ESTIMATE, forward then inverse), as text.
std::string plans_made(int size) {
    float* time = fftwf_alloc_real(static_cast<size_t>(size));
    fftwf_complex* spectrum = fftwf_alloc_complex(static_cast<size_t>(size / 2 + 1));
    std::string text;
    for (fftwf_plan p : {fftwf_plan_dft_r2c_1d(size, time, spectrum, FFTW_ESTIMATE),
                         fftwf_plan_dft_c2r_1d(size, spectrum, time, FFTW_ESTIMATE)}) {
        char* printed = fftwf_sprint_plan(p);
        text += printed;
        std::free(printed);
        fftwf_destroy_plan(p);
    }
    fftwf_free(time);
    fftwf_free(spectrum);
    return text;
}

// The wisdom recorded at build time (fft_wisdom_generator.cpp) is taken by this FFTW and leads
// its planner to the plans it makes without it: the same transforms, bit for bit.
TEST(FftWisdom, EachEntryGivesThePlansFftwMakesWithout) {
    ASSERT_GT(kFftWisdomEntries, 100);
    for (int i = 0; i < kFftWisdomEntries; ++i) {
        const FftWisdom& entry = kFftWisdom[i];
        if (i > 0) {
            ASSERT_GT(entry.size, kFftWisdom[i - 1].size) << "in increasing order";
        }
        fftwf_forget_wisdom();
        const std::string without = plans_made(entry.size);
        fftwf_forget_wisdom();
        ASSERT_EQ(fftwf_import_wisdom_from_string(entry.wisdom), 1) << "size " << entry.size;
        EXPECT_EQ(plans_made(entry.size), without) << "size " << entry.size;
    }
}

}  // namespace
}  // namespace tactus
