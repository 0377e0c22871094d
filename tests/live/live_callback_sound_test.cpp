// The player's sound on `tactus live`'s sound channels: each channel of the file on its sound
// channel in turn (more sound channels than the file's repeat it, fewer leave the rest out),
// with --sync delayed by the sync delay, sample for sample.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "live/live_callback.hpp"
#include "live/player.hpp"
#include "support/sound_file.hpp"
#include "support/temp_dir.hpp"

namespace tactus::live {
namespace {

constexpr double kRateHz = 48000;
constexpr int kFrames = 4000, kOutputs = 5;

class LiveCallbackSound : public test::TempDirTest {
  protected:
    void SetUp() override {
        test::TempDirTest::SetUp();
        std::vector<float> stereo(2 * kFrames);
        for (int i = 0; i < kFrames; ++i) {
            stereo[2 * static_cast<size_t>(i)] = source(0, i);
            stereo[2 * static_cast<size_t>(i) + 1] = source(1, i);
        }
        ASSERT_NO_FATAL_FAILURE(test::write_sound_file(dir_ / "in.wav", stereo, kRateHz, 2));
    }
    static float source(int channel, int i) {  // exact in float: any misplaced sample shows
        return static_cast<float>(i + 1) / 8192 * (channel == 0 ? 1.0f : -0.5f);
    }
    // Every device channel, 3000 samples or a little more, played in blocks of odd sizes.
    std::vector<std::vector<float>> play(const std::vector<int>& sound_channels, int sync) {
        Player player({dir_ / "in.wav"}, kRateHz, /*loop=*/false);
        Engine engine;
        engine.prepare({.sample_rate_hz = kRateHz, .max_block = 512, .channels = 2});
        LiveCallback callback(engine, &player,
                              {.device_outputs = kOutputs,
                               .actuator_channels = {0},
                               .sound_channels = sound_channels},
                              sync);
        callback.begin();
        std::vector<std::vector<float>> device(kOutputs);
        std::vector<float> out(kOutputs * 512);
        for (int done = 0, b = 0; done < 3000; ++b) {
            const int frames = 17 + b * 37 % 480;
            callback.process(nullptr, out.data(), frames);
            for (int c = 0; c < kOutputs; ++c)
                device[c].insert(device[c].end(), out.begin() + c * frames,
                                 out.begin() + (c + 1) * frames);
            done += frames;
        }
        return device;
    }
};

TEST_F(LiveCallbackSound, EachChannelOfTheFileOnItsSoundChannelsDelayedBySync) {
    for (const int sync : {kNoSync, 0, 100}) {
        const int delay = sync == kNoSync ? 0 : sync;
        for (const auto& sound_channels : {std::vector<int>{1, 2, 3}, std::vector<int>{4}}) {
            const auto device = play(sound_channels, sync);
            for (size_t s = 0; s < sound_channels.size(); ++s) {
                const auto& heard = device[static_cast<size_t>(sound_channels[s])];
                for (size_t i = 0; i < heard.size(); ++i) {
                    const int at = static_cast<int>(i) - delay;
                    ASSERT_EQ(heard[i], at < 0 ? 0.0f : source(static_cast<int>(s % 2), at))
                        << "sync " << sync << ", sound channel " << sound_channels[s] << ", sample "
                        << i;
                }
            }
            for (int c = 1; c < kOutputs; ++c) {  // the channels nothing drives stay silent
                if (std::find(sound_channels.begin(), sound_channels.end(), c) !=
                    sound_channels.end())
                    continue;
                for (const float x : device[static_cast<size_t>(c)]) ASSERT_EQ(x, 0.0f) << c;
            }
        }
    }
}

}  // namespace
}  // namespace tactus::live
