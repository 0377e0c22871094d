#include "tactus/engine/input_ring.hpp"

namespace tactus {

void InputRing::prepare(int64_t capacity) {
    samples_ = std::make_unique<std::atomic<float>[]>(static_cast<size_t>(capacity));
    capacity_ = capacity;
    reset();
}

void InputRing::reset() noexcept {
    for (int64_t i = 0; i < capacity_; ++i) samples_[i].store(0.0f, std::memory_order_relaxed);
    written_.store(0, std::memory_order_release);
}

void InputRing::write(const float* samples, int count) noexcept {
    const int64_t start = written_.load(std::memory_order_relaxed);
    int64_t slot = start % capacity_;
    for (int i = 0; i < count; ++i) {
        samples_[slot].store(samples[i], std::memory_order_relaxed);
        if (++slot == capacity_) slot = 0;
    }
    written_.store(start + count, std::memory_order_release);
}

bool InputRing::read(int64_t from, float* out, int count) const noexcept {
    const auto held = [&] {
        const int64_t now = written();
        return from >= 0 && from >= now - capacity_ && from + count <= now;
    };
    if (!held()) return false;
    for (int i = 0; i < count; ++i)
        out[i] = samples_[(from + i) % capacity_].load(std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_acquire);
    return held();
}

}  // namespace tactus
