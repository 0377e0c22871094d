// Every stream processor keeps the one contract (dsp/process_spec.hpp): prepare() takes a
// ProcessSpec first and its own settings by name, reset() cannot throw, latency() says the
// delay in samples. Checked at compile time; the values of latency() where they are known.
#include <gtest/gtest.h>

#include "tactus/actuator/compensation.hpp"
#include "tactus/analysis/analyzer.hpp"
#include "tactus/dsp/dc_blocker.hpp"
#include "tactus/dsp/fitted_eq.hpp"
#include "tactus/dsp/process_spec.hpp"
#include "tactus/dsp/upsampler.hpp"
#include "tactus/engine/actuator_chain.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/engine/output_trim.hpp"
#include "tactus/engine/pipeline.hpp"
#include "tactus/post/band_limit.hpp"
#include "tactus/post/flattening_filter.hpp"
#include "tactus/post/peak_limiter.hpp"
#include "tactus/post/post_chain.hpp"
#include "tactus/synthesis/flutter.hpp"
#include "tactus/synthesis/pressure.hpp"
#include "tactus/synthesis/voice.hpp"

namespace tactus {
namespace {

static_assert(Processor<DcBlocker> && Processor<Analyzer>);
static_assert(Processor<Voice> && Processor<Flutter> && Processor<Pressure>);
static_assert(Processor<BandLimit> && Processor<FlatteningFilter> && Processor<FittedEq> &&
              Processor<ActuatorCompensation> && Processor<PeakLimiter> && Processor<PostChain>);
static_assert(Processor<Upsampler> && Processor<OutputTrim> && Processor<ActuatorChain> &&
              Processor<Pipeline> && Processor<Engine>);

// prepare() takes the spec first; what follows is the processor's own, by name or by type.
static_assert(requires(DcBlocker p) { p.prepare(ProcessSpec{}); });
static_assert(requires(Analyzer p) { p.prepare(ProcessSpec{}, Settings{}); });
static_assert(requires(Voice p) { p.prepare(ProcessSpec{}, 1000.0); });
static_assert(requires(Flutter p) { p.prepare(ProcessSpec{}); });
static_assert(requires(Pressure p) { p.prepare(ProcessSpec{}); });
static_assert(requires(BandLimit p) { p.prepare(ProcessSpec{}, BandEdges{}); });
static_assert(requires(FlatteningFilter p) { p.prepare(ProcessSpec{}, FlatteningDesign{}); });
static_assert(requires(FittedEq p) { p.prepare(ProcessSpec{}, FittedEq::Design{}); });
static_assert(requires(ActuatorCompensation p, ActuatorProfile a) { p.prepare(ProcessSpec{}, a); });
static_assert(requires(PeakLimiter p) { p.prepare(ProcessSpec{}, 1.5, LimiterLevels{}); });
static_assert(requires(PostChain p) { p.prepare(ProcessSpec{}, Settings{}); });
static_assert(requires(Upsampler p) { p.prepare(ProcessSpec{}, 4); });
static_assert(requires(OutputTrim p) { p.prepare(ProcessSpec{}, ActuatorOutput{}); });
static_assert(requires(ActuatorChain p) { p.prepare(ProcessSpec{}, 4, Settings{}, nullptr); });
static_assert(requires(Pipeline p) { p.prepare(ProcessSpec{}, Settings{}, {ActuatorOutput{}}); });
static_assert(requires(Engine p) { p.prepare(ProcessSpec{}); });
// Rates, edges and thresholds in a row, which a call could swap, are gone.
template <typename T>
concept PreparesFromBareNumbers = requires(T p) {
    p.prepare(48000.0, 20.0, 1000.0, 8);
};
static_assert(!PreparesFromBareNumbers<BandLimit> && !PreparesFromBareNumbers<PitchYin>);

TEST(ProcessorContract, LatencyIsTheDelayInSamples) {
    const ProcessSpec spec{.sample_rate_hz = 48000, .max_block = 64};
    PeakLimiter limiter;
    limiter.prepare(spec, 2.0, {});
    EXPECT_EQ(limiter.latency(), 96);
    OutputTrim trim;
    trim.prepare(spec, {.profile = {}, .gain_db = 0, .delay_ms = 5});
    EXPECT_EQ(trim.latency(), 240);
    BandLimit band;
    band.prepare(spec, {});
    EXPECT_EQ(band.latency(), 0);
    Engine engine;
    engine.prepare(spec);
    PostChain post;
    post.prepare({.sample_rate_hz = 48000.0 / engine.rate_divisor(), .max_block = 64}, Settings{});
    // The engine's latency: its post chain's look-ahead (less the upsampler's share) plus the
    // upsampler, within one internal sample of post.lookahead_ms.
    EXPECT_NEAR(engine.latency(), post.latency() * engine.rate_divisor(), engine.rate_divisor());
}

}  // namespace
}  // namespace tactus
