// What a process has designed once it does not design again: FFT plans (one pair per size for
// the process), equaliser fits (by their exact inputs) and so a second engine prepared like the
// first; what the build designed (the default flattening) it does not design at all. Counted as
// allocator calls (support/allocation_counter.hpp): planning and fitting allocate all along, taking
// what was made allocates only the new object's own buffers. The designs taken are the ones made:
// the same coefficients, bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "support/allocation_counter.hpp"
#include "tactus/dsp/fitted_eq.hpp"
#include "tactus/dsp/real_fft.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/engine/pipeline.hpp"
#include "tactus/post/flattening_inputs.hpp"

using tactus::test::g_allocator_calls;
using tactus::test::Guard;
using tactus::test::reset_counts;

namespace tactus {
namespace {

// Allocator calls `make` makes on this thread.
template <typename F>
long allocations(F&& make) {
    reset_counts();
    {
        Guard guard;
        make();
    }
    return g_allocator_calls.load();
}

TEST(PrepareAgain, AnFftSizePlannedBeforeTakesItsPlans) {
    constexpr int kSize = 1000;  // a size nothing else in this executable plans
    RealFft first, second;
    const long planned = allocations([&] { first.prepare(kSize); });
    const long taken = allocations([&] { second.prepare(kSize); });
    EXPECT_LE(taken, 4) << "its two buffers, and freeing none: " << planned << " then " << taken;
    // Both transform alike with the shared plans.
    for (int i = 0; i < kSize; ++i) first.time()[i] = second.time()[i] = std::sin(0.1f * i);
    first.forward();
    second.forward();
    for (int k = 0; k < first.bins(); ++k) ASSERT_EQ(first.spectrum()[k], second.spectrum()[k]);
}

TEST(PrepareAgain, AFitMadeBeforeIsTakenBitForBit) {
    const auto target = [](double f) { return -6.0 * std::log2(f / 37.0); };
    const FitBand band{.low_hz = 23, .high_hz = 900};
    FittedEq::Design first, again;
    const long fitted = allocations([&] { first = FittedEq::fit(11025, band, target); });
    const long taken = allocations([&] { again = FittedEq::fit(11025, band, target); });
    EXPECT_GT(fitted, 10 * taken) << fitted << " then " << taken;
    ASSERT_EQ(again.count, first.count);
    EXPECT_EQ(again.gain, first.gain);
    for (int s = 0; s < first.count; ++s) {
        const BiquadCoefficients &a = first.sections[s], &b = again.sections[s];
        EXPECT_TRUE(a.b0 == b.b0 && a.b1 == b.b1 && a.b2 == b.b2 && a.a1 == b.a1 && a.a2 == b.a2)
            << "section " << s;
    }
    // Another rate is another fit.
    EXPECT_GT(allocations([&] { (void)FittedEq::fit(12000, band, target); }), 10 * taken);
}

TEST(PrepareAgain, ASecondEngineDesignsNothingTheFirstDid) {
    Settings settings;
    settings.set(P::analysis_window_ms, 37);  // sizes nothing else in this executable plans
    Engine first(settings), second(settings);
    const long designed = allocations([&] { first.prepare(44100, 256); });
    const long taken = allocations([&] { second.prepare(44100, 256); });
    EXPECT_LT(10 * taken, designed) << designed << " then " << taken;
}

// The default settings' flattening design at the usual rates is the one made at build time
// (post/flattening_designs.hpp): a process's first engine takes it without fitting (no
// allocation), and it is what the fit makes, bit for bit.
TEST(PrepareAgain, TheDefaultFlatteningDesignIsTheBuildsBitForBit) {
    const FlatteningDesign inputs = flattening_inputs(Settings{});
    for (double output_hz : {44100.0, 48000.0, 96000.0}) {
        const double rate = output_hz / Pipeline::rate_divisor_for(output_hz);
        FlatteningFilter::Design taken;
        EXPECT_EQ(allocations([&] { taken = FlatteningFilter::design(rate, inputs); }), 0)
            << output_hz;
        const FlatteningFilter::Design made = FlatteningFilter::make_design(rate, inputs);
        EXPECT_TRUE(taken.inputs == made.inputs);
        EXPECT_EQ(taken.reference_db, made.reference_db);
        ASSERT_EQ(taken.eq.count, made.eq.count);
        EXPECT_EQ(taken.eq.gain, made.eq.gain);
        for (int s = 0; s < made.eq.count; ++s) {
            const BiquadCoefficients &a = taken.eq.sections[s], &b = made.eq.sections[s];
            EXPECT_TRUE(a.b0 == b.b0 && a.b1 == b.b1 && a.b2 == b.b2 && a.a1 == b.a1 &&
                        a.a2 == b.a2)
                << output_hz << " section " << s;
        }
    }
}

}  // namespace
}  // namespace tactus
