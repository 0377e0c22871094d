// The same music at any input rate gives the same onsets (engine.hpp, "Rates"): the Amen break
// (Sonic Pi's loop_amen_full.flac, read through libsndfile) brought from 44.1 kHz to 22.05, 48
// and 96 kHz by exact band-limited interpolation (its spectrum, zero-padded or truncated), then
// run through the default engine at each rate. Every rate must find as many onsets as 44.1 kHz,
// each within 1 ms of its 44.1 kHz counterpart.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <vector>

#include "support/engine_blocks.hpp"
#include "tactus/dsp/real_fft.hpp"
#include "tactus/engine/engine.hpp"
#include "tactus/io/audio_reader.hpp"

namespace tactus {
namespace {

const std::filesystem::path kAmen = "/usr/share/sonic-pi/samples/loop_amen_full.flac";
constexpr double kReferenceHz = 44100;
constexpr double kToleranceS = 0.001;

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

std::vector<double> onsets_s(const std::vector<float>& x, double rate_hz) {
    Engine engine;
    engine.prepare(rate_hz, 512);
    Onsets onsets(rate_hz);
    engine.set_observer(&onsets);
    test::process_in_blocks(engine, x, 512);
    return onsets.times_s;
}

TEST(SampleRates, TheAmenBreakHasTheSameOnsetsAt22To96kHz) {
    const MonoAudio amen = read_mono(kAmen);
    ASSERT_EQ(amen.sample_rate_hz, kReferenceHz);
    // The reference goes through the same padding: the file's abrupt end, then silence.
    const std::vector<double> reference =
        onsets_s(resampled(amen.samples, kReferenceHz), kReferenceHz);
    ASSERT_GT(reference.size(), 30u);
    for (const double rate_hz : {22050.0, 48000.0, 96000.0}) {
        const std::vector<double> found = onsets_s(resampled(amen.samples, rate_hz), rate_hz);
        ASSERT_EQ(found.size(), reference.size()) << rate_hz << " Hz";
        for (size_t i = 0; i < found.size(); ++i)
            EXPECT_NEAR(found[i], reference[i], kToleranceS) << rate_hz << " Hz, onset " << i;
    }
}

}  // namespace
}  // namespace tactus
