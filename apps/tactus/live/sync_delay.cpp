#include "sync_delay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tactus/engine/engine.hpp"

namespace tactus::live {
namespace {

constexpr int kHits = 9;            // phases over one hop
constexpr double kSpacingS = 0.45;  // apart: each pulse has decayed before the next hit
constexpr double kLeadS = 0.3;      // silence before the first hit
constexpr double kHitDecayS = 0.03, kClickDecayS = 0.004, kToneHz = 80;

}  // namespace

int vibration_delay_samples(const Settings& settings, double sample_rate_hz,
                            const std::optional<ActuatorProfile>& actuator) {
    Engine engine(settings);
    engine.set_actuator(actuator);
    engine.prepare(sample_rate_hz, Engine::kMaxBlock);
    const double hop = engine.hop_samples();
    const auto spacing = static_cast<int64_t>(kSpacingS * sample_rate_hz);
    std::vector<int64_t> hits;
    hits.reserve(kHits);
    for (int k = 0; k < kHits; ++k)
        hits.push_back(static_cast<int64_t>(kLeadS * sample_rate_hz) + k * spacing +
                       static_cast<int64_t>(std::lround(k * hop / kHits)));
    std::vector<float> x(static_cast<size_t>(hits.back() + spacing)), y(x.size());
    uint32_t noise = 12345;  // a fixed LCG: the same hits every time
    for (const int64_t at : hits)
        for (int64_t i = 0; i < spacing / 2; ++i) {
            const double t = static_cast<double>(i) / sample_rate_hz;
            noise = noise * 1664525u + 1013904223u;
            const double white = static_cast<double>(noise) / 4294967296.0 * 2 - 1;
            x[static_cast<size_t>(at + i)] += static_cast<float>(
                0.8 * std::exp(-t / kHitDecayS) * std::sin(2 * M_PI * kToneHz * t + 0.5) +
                0.3 * std::exp(-t / kClickDecayS) * white);
        }
    for (size_t done = 0; done < x.size();) {
        const int count = static_cast<int>(std::min<size_t>(x.size() - done, Engine::kMaxBlock));
        engine.process(x.data() + done, y.data() + done, count);
        done += static_cast<size_t>(count);
    }
    std::vector<int64_t> delays;
    for (const int64_t at : hits) {
        const auto from = y.begin() + at,
                   to = y.begin() +
                        std::min<int64_t>(at + max_vibration_delay_samples(sample_rate_hz),
                                          static_cast<int64_t>(y.size()));
        float peak = 0;
        for (auto i = from; i != to; ++i) peak = std::max(peak, std::abs(*i));
        if (peak <= 0) continue;
        const auto rise = std::find_if(
            from, to, [&](float v) { return std::abs(v) >= kPulseRiseFraction * peak; });
        delays.push_back(rise - from);
    }
    if (delays.empty())  // settings that never pulse: the look-ahead
        return std::min(engine.latency(), max_vibration_delay_samples(sample_rate_hz));
    std::nth_element(delays.begin(), delays.begin() + static_cast<long>(delays.size() / 2),
                     delays.end());
    return static_cast<int>(delays[delays.size() / 2]);
}

int max_vibration_delay_samples(double sample_rate_hz) {
    return static_cast<int>(kSpacingS * sample_rate_hz) - 1;
}

VibrationDelay::VibrationDelay(const Settings& settings, double sample_rate_hz,
                               std::optional<ActuatorProfile> actuator)
    : measured_(settings),
      sample_rate_hz_(sample_rate_hz),
      actuator_(std::move(actuator)),
      samples_(vibration_delay_samples(settings, sample_rate_hz, actuator_)) {}

bool VibrationDelay::follow(const Settings& running, double now_s) {
    if (running == measured_ || now_s - measured_at_s_ < kRemeasurePeriodS) return false;
    measured_ = running;
    measured_at_s_ = now_s;
    const int was = samples_;
    samples_ = vibration_delay_samples(running, sample_rate_hz_, actuator_);
    return samples_ != was;
}

}  // namespace tactus::live
