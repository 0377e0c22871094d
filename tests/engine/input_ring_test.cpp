// InputRing: what a control thread copies is what the audio thread wrote, and a range the audio
// thread may be overwriting at that moment (within one write of the oldest held sample) is
// refused; a reader and the writer on two threads (under ThreadSanitizer in make test-tsan).
#include "tactus/engine/input_ring.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace tactus {
namespace {

constexpr int kMaxWrite = 10;
constexpr int64_t kCapacity = 100;

// Sample `n` as the ring holds it: exact in a float (below 2^24).
float sample(int64_t n) {
    return static_cast<float>(n & 0xffffff);
}

void write_counting(InputRing& ring, int64_t& next, int count) {
    std::vector<float> block(static_cast<size_t>(count));
    for (float& x : block) x = sample(next++);
    const float* lanes[] = {block.data()};
    ring.write(lanes, count);
}

TEST(InputRing, RefusesWhatTheNextWriteMayOverwrite) {
    InputRing ring;
    ring.prepare(1, kCapacity, kMaxWrite);
    int64_t next = 0;
    for (int k = 0; k < 15; ++k) write_counting(ring, next, kMaxWrite);  // 150 written
    std::vector<float> copy(20);
    float* lanes[] = {copy.data()};
    EXPECT_FALSE(ring.read(50, lanes, 20)) << "overwritten";
    EXPECT_FALSE(ring.read(55, lanes, 20)) << "held, but the next write may be overwriting it";
    ASSERT_TRUE(ring.read(60, lanes, 20));
    for (int i = 0; i < 20; ++i) EXPECT_EQ(copy[static_cast<size_t>(i)], 60.0f + i);
    EXPECT_FALSE(ring.read(140, lanes, 20)) << "not yet written";
}

// Every copy the ring accepts holds the samples written there, while the writer runs on.
TEST(InputRing, CopiesWhatWasWrittenWhileWriting) {
    InputRing ring;
    ring.prepare(1, kCapacity, kMaxWrite);
    std::atomic<bool> stop{false};
    std::thread audio([&] {
        int64_t next = 0;
        while (!stop.load(std::memory_order_relaxed)) write_counting(ring, next, 7);
    });
    int accepted = 0, wrong = 0;
    std::vector<float> copy(30);
    float* lanes[] = {copy.data()};
    while (accepted < 2000) {
        const int64_t from = ring.written() - 60;
        if (from < 0 || !ring.read(from, lanes, 30)) continue;
        ++accepted;
        for (int i = 0; i < 30; ++i) wrong += copy[static_cast<size_t>(i)] != sample(from + i);
    }
    stop = true;
    audio.join();
    EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace tactus
