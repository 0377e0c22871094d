// The same music at any input rate gives the same onsets (engine.hpp, "Rates"): the Amen break
// (Sonic Pi's loop_amen_full.flac, read through libsndfile) brought from 44.1 kHz to 22.05, 48
// and 96 kHz by exact band-limited interpolation (its spectrum, zero-padded or truncated), then
// run through the default engine at each rate. Every rate must find as many onsets as 44.1 kHz,
// each within 1 ms of its 44.1 kHz counterpart from the 16 kHz analysis and the low band; the
// input's high band (6-10 kHz, analysis/band_power.hpp, from 22.05 kHz up), filtered at each rate,
// may tip an onset's decision by a frame or three, which moves its estimated start by up to 5 ms
// (20 ms at 22.05 kHz, where the band's top edge is near Nyquist).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <vector>

#include "support/engine_blocks.hpp"
#include "support/sounds.hpp"
#include "tactus/dsp/real_fft.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"

namespace tactus {
namespace {

using tactus::test::kAmen;
constexpr double kReferenceHz = 44100;
constexpr double kToleranceS = 0.001, kWithHighBandToleranceS = 0.005;
// At 22.05 kHz the high band's top edge sits near Nyquist: two of the Amen break's onsets are
// decided on a later rise, 11 and 17 ms on.
constexpr double kAtItsEdgeToleranceS = 0.02;

// x at rate_hz (a multiple of 44.1 kHz / 882 = 50 Hz), by its DFT: the file is padded with
// silence to a multiple of 882 samples so that both lengths are whole.
std::vector<float> resampled(const std::vector<float>& x, double rate_hz) {
    constexpr size_t kPeriod = 882;
    const int n = static_cast<int>((x.size() + 4410) / kPeriod * kPeriod);
    const int m = static_cast<int>(std::lround(n * rate_hz / kReferenceHz));
    RealFft in, out;
    in.prepare(n);
    out.prepare(m);
    std::fill_n(in.time(), n, 0.0f);
    std::copy(x.begin(), x.end(), in.time());
    in.forward();
    const int shared = std::min(in.bins(), out.bins()) - 1;  // Nyquist bins left out
    std::fill_n(out.spectrum(), out.bins(), std::complex<float>{});
    std::copy_n(in.spectrum(), shared, out.spectrum());
    out.inverse();
    std::vector<float> y(out.time(), out.time() + m);
    for (float& v : y) v /= static_cast<float>(n);
    return y;
}

class Onsets final : public FrameObserver {
  public:
    explicit Onsets(double rate_hz) : rate_hz_(rate_hz) {}
    void on_frame(const Features& f, const ControlFrame&) noexcept override {
        if (f.onset) times_s.push_back(static_cast<double>(f.onset_sample) / rate_hz_);
    }
    std::vector<double> times_s;

  private:
    double rate_hz_;
};

std::vector<double> onsets_s(const std::vector<float>& x, double rate_hz, double high_weight) {
    Engine engine;
    Settings settings;
    settings.set(P::onset_high_weight, high_weight);
    engine.set(settings);
    engine.prepare(rate_hz, 512);
    Onsets onsets(rate_hz);
    engine.set_observer(&onsets);
    test::process_in_blocks(engine, x, 512);
    return onsets.times_s;
}

TEST(SampleRates, TheAmenBreakHasTheSameOnsetsAt22To96kHz) {
    const MonoAudio amen = read_mono(kAmen);
    ASSERT_EQ(amen.sample_rate_hz, kReferenceHz);
    const double default_weight = Settings{}[P::onset_high_weight];
    struct Case {
        double high_weight, tolerance_s;
        std::vector<double> rates_hz;
    };
    for (const Case& c : {Case{0.0, kToleranceS, {22050.0, 48000.0, 96000.0}},
                          Case{default_weight, kWithHighBandToleranceS, {48000.0, 96000.0}},
                          Case{default_weight, kAtItsEdgeToleranceS, {22050.0}}}) {
        const double high_weight = c.high_weight, tolerance_s = c.tolerance_s;
        // The reference goes through the same padding: the file's abrupt end, then silence.
        const std::vector<double> reference =
            onsets_s(resampled(amen.samples, kReferenceHz), kReferenceHz, high_weight);
        ASSERT_GT(reference.size(), 30u);
        for (const double rate_hz : c.rates_hz) {
            const std::vector<double> found =
                onsets_s(resampled(amen.samples, rate_hz), rate_hz, high_weight);
            ASSERT_EQ(found.size(), reference.size()) << rate_hz << " Hz";
            for (size_t i = 0; i < found.size(); ++i)
                EXPECT_NEAR(found[i], reference[i], tolerance_s)
                    << rate_hz << " Hz, onset " << i << ", onset.high_weight " << high_weight;
        }
    }
}

}  // namespace
}  // namespace tactus
