// Post-processing in the paper's order (§6): band-limit to the vibrotactile range, P-channel
// flattening, peak limiter, band-limit again; without an actuator the first band-limit is its
// high-pass alone (post_chain.cpp). The limiter's ceiling sits 1 dB under the output
// ceiling to leave room for the last band-limit's ringing; a final clip at the ceiling makes the
// bound absolute and counts how often it had to act (it should not: see clipped_samples()).
// With an actuator profile, its compensation follows the flattening (so the limiter bounds what
// the actuator receives) and the ceiling is at most the actuator's max drive; without one the
// chain is unchanged.
// Routing of the low-frequency channel components (synthesis/voice.hpp), which the band-limit
// (30 Hz high-pass) and the P flattening filter would remove or distort:
//   carrier -> band-limit -> P flattening -(+ flutter)-> actuator compensation -> limiter
//           -> band-limit -(+ pressure)-> clip
// The NPI flutter (2-40 Hz, already confined to its band by synthesis) joins after the
// flattening, through an optional 30 Hz peaking filter (paper §5.2 note 4), so the actuator
// compensation shapes and the limiter guards the sum; the last band-limit's high-pass then sits
// at post.flutter_low_hz. The NPIII pressure (a slow offset) joins after the last band-limit; the
// limiter's ceiling is lowered by the pressure's largest value (its weight times the ceiling),
// so the sum stays under the ceiling. It is not delayed by the limiter's look-ahead (0.3 ms
// against NPIII's >= 330 ms periods). With both off and no actuator the chain is the paper's
// (its first low-pass aside).
// An ERM (its vibration frequency follows its speed: only the carrier's intensity can reach the
// skin) takes the carrier's intensity instead, shaped for its spin-up (erm_drive.hpp):
//   carrier -> band-limit -> limiter -> ERM drive -> clip
// without the flattening (a carrier frequency the skin never feels) and the compensation (its
// response is its speed's, not the drive's spectrum's); the flutter and pressure are off on it
// (actuator/fit.hpp).
#pragma once

#include <algorithm>
#include <cstdint>

#include "tactus/actuator/compensation.hpp"
#include "tactus/core/units.hpp"
#include "tactus/params/params.hpp"
#include "tactus/post/band_limit.hpp"
#include "tactus/post/erm_drive.hpp"
#include "tactus/post/flattening_filter.hpp"
#include "tactus/post/peak_limiter.hpp"

namespace tactus {

// The flattening filter `settings` ask for at a post chain's rate (allocates: a control thread
// designs it, PostChain::glide_flattening() takes it live).
FlatteningFilter::Design flattening_design(double sample_rate_hz, const Settings& settings);

class PostChain {
  public:
    static constexpr int kFirstBandOrder = 8;
    static constexpr int kLastBandOrder = 2;
    static constexpr double kRingingMarginDb = 1.0;

    // May allocate. `actuator` may be null (no compensation).
    void prepare(const ProcessSpec& spec, const Settings& settings,
                 const ActuatorProfile* actuator = nullptr);
    void reset() noexcept;
    // Live (audio thread), each over `glide_samples`: drive, limiter threshold, ceiling (and the
    // pressure headroom under it) and the flutter's peaking filter; release at once.
    void set_live(const Settings& settings, int glide_samples) noexcept;
    // The output ceiling `settings` give this chain (post.ceiling_db, at most the actuator's
    // max drive).
    double ceiling_for(const Settings& settings) const noexcept {
        return std::min(db_to_gain(settings[P::post_ceiling_db]), max_drive_);
    }
    void glide_flattening(const FlatteningFilter::Design& design, int glide_samples) noexcept {
        flatten_.glide_to(design, glide_samples);
    }
    // The carrier alone (flutter and pressure off).
    void process(float* samples, int count) noexcept { process(samples, nullptr, nullptr, count); }
    // carrier: in place, becomes the output. flutter (filtered in place) and pressure may be
    // null; each is used only when its component is on (params/components.hpp).
    void process(float* carrier, float* flutter, const float* pressure, int count) noexcept;
    int latency() const { return limiter_.latency(); }
    int64_t clipped_samples() const { return clipped_; }
    double ceiling() const { return ceiling_; }
    const FlatteningFilter& flattening() const { return flatten_; }

  private:
    BandLimit first_band_, last_band_;
    FlatteningFilter flatten_;
    ActuatorCompensation compensation_;
    bool compensate_ = false;
    bool erm_ = false;
    ErmDrive erm_drive_;
    PeakLimiter limiter_;
    Biquad flutter_peak_;
    bool flutter_on_ = false, flutter_peak_on_ = false, pressure_on_ = false;
    double sample_rate_hz_ = 48000;
    double max_drive_ = 1.0;                     // the actuator's, 1 without one
    double ceiling_ = 1.0, clip_ceiling_ = 1.0;  // clip_ceiling_: the higher during a glide
    int64_t clipped_ = 0;
};

}  // namespace tactus
