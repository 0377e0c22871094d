#include "tactus/engine/live_settings.hpp"

#include <cmath>

namespace tactus {

void LiveSettings::prepare(const Settings& settings, double frames_per_second) noexcept {
    now_ = settings;
    frames_per_second_ = frames_per_second;
    frames_left_.fill(0);
    gliding_count_ = 0;
    changed_ = false;
}

void LiveSettings::ask(P id, double value) noexcept {
    const auto i = static_cast<size_t>(id);
    const auto frames =
        static_cast<int>(std::ceil(spec(id).smoothing_ms * 1e-3 * frames_per_second_));
    if (frames <= 1) {
        now_.assign(id, value);
        if (frames_left_[i] > 0) frames_left_[i] = 1;  // its glide ends at the next step
        target_[i] = value;
        step_[i] = 0.0;
        changed_ = true;
        return;
    }
    if (frames_left_[i] == 0) gliding_[gliding_count_++] = id;
    target_[i] = value;
    step_[i] = (value - now_[id]) / frames;
    frames_left_[i] = frames;
}

bool LiveSettings::step() noexcept {
    bool moved = false;
    for (int k = 0; k < gliding_count_;) {
        const P id = gliding_[k];
        const auto i = static_cast<size_t>(id);
        if (--frames_left_[i] == 0) {
            now_.assign(id, target_[i]);  // exactly where it was asked to go
            gliding_[k] = gliding_[--gliding_count_];
        } else {
            now_.assign(id, now_[id] + step_[i]);
            ++k;
        }
        moved = true;
    }
    return moved;
}

}  // namespace tactus
