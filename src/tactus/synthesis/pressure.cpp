#include "tactus/synthesis/pressure.hpp"

#include "tactus/core/units.hpp"
#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {
constexpr double kNpiiiHighHz = perception::info(perception::Channel::NPIII).range_high_hz;
constexpr double kGlideMs = 1e3 / (2.0 * kPi * kNpiiiHighHz);
constexpr double kSilentLevel = 1e-9;
}  // namespace

void Pressure::prepare(double sample_rate_hz) {
    glide_ = one_pole_coefficient(kGlideMs, sample_rate_hz);
    reset();
}

void Pressure::render(float* out, int count) noexcept {
    double level = level_;
    const double target = target_, g = glide_;
    for (int i = 0; i < count; ++i) {
        level = target + g * (level - target);
        if (target == 0.0 && level < kSilentLevel) level = 0.0;
        out[i] = static_cast<float>(level);
    }
    level_ = level;
}

}  // namespace tactus
