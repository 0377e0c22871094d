// SampleHistory: the newest samples read back oldest-first across ring wrap-around, zeros before
// the stream starts, written() counts everything, any write split gives the same contents.
#include "tactus/dsp/sample_history.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tactus {
namespace {

TEST(SampleHistory, ReadsTheNewestSamplesOldestFirstAcrossWraps) {
    SampleHistory history;
    history.prepare(100);  // rounded up to 128
    std::vector<float> all;
    for (int block = 0; block < 50; ++block) {
        std::vector<float> x(static_cast<size_t>(1 + block % 13));
        for (auto& v : x) v = static_cast<float>(all.size() + (&v - x.data()) + 1);
        history.write(x.data(), static_cast<int>(x.size()));
        all.insert(all.end(), x.begin(), x.end());
        ASSERT_EQ(history.written(), static_cast<int64_t>(all.size()));
        const int count = std::min<int>(100, static_cast<int>(all.size()));
        std::vector<float> out(static_cast<size_t>(count));
        history.read_latest(out.data(), count);
        for (int i = 0; i < count; ++i)
            ASSERT_EQ(out[i], all[all.size() - count + i]) << "block " << block << ", " << i;
    }
}

TEST(SampleHistory, ZerosBeforeTheStream) {
    SampleHistory history;
    history.prepare(64);
    const float x[3] = {1, 2, 3};
    history.write(x, 3);
    std::vector<float> out(10, -1.0f);
    history.read_latest(out.data(), 10);
    const std::vector<float> expected = {0, 0, 0, 0, 0, 0, 0, 1, 2, 3};
    EXPECT_EQ(out, expected);
}

TEST(SampleHistory, ResetForgetsEverything) {
    SampleHistory history;
    history.prepare(16);
    std::vector<float> x(40, 5.0f);
    history.write(x.data(), 40);
    history.reset();
    EXPECT_EQ(history.written(), 0);
    std::vector<float> out(16, -1.0f);
    history.read_latest(out.data(), 16);
    for (float v : out) EXPECT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace tactus
