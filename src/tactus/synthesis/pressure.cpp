#include "tactus/synthesis/pressure.hpp"

#include "tactus/perception/channels.hpp"

namespace tactus {
namespace {
constexpr double kNpiiiHighHz = perception::info(perception::Channel::NPIII).range_high_hz;
}  // namespace

void Pressure::prepare(const ProcessSpec& spec) {
    glide_.prepare(spec, corner_time_constant_ms(kNpiiiHighHz));
    reset();
}

void Pressure::process(float* out, int count) noexcept {
    double level = level_;
    const Glide glide = glide_;
    for (int i = 0; i < count; ++i) {
        out[i] = static_cast<float>(level);
        level = glide.step(level, target_);
    }
    level_ = level;
}

}  // namespace tactus
