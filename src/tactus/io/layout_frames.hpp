// The channels of a layout's file or device, block by block (io/layout_file.hpp): each output's
// vibration on its channel, the sound on the sound channels (the input's channels in turn, again
// from the first when there are more sound channels, as tactus live plays them), silence on the
// others.
#pragma once

#include <algorithm>
#include <vector>

#include "tactus/io/audio_reader.hpp"
#include "tactus/io/layout_file.hpp"

namespace tactus {

class LayoutFrames {
  public:
    // Allocates.
    LayoutFrames(const Layout& layout, int max_frames)
        : layout_(layout), block_(layout.channels, max_frames) {
        for (int c = 0; c < layout.channels; ++c) std::fill_n(block_[c], max_frames, 0.0f);
    }
    // The sound of the next block (input_channels channels).
    void set_sound(const float* const* input, int input_channels, int frames) {
        const auto& sound = layout_.sound_channels;
        for (size_t i = 0; i < sound.size(); ++i)
            std::copy_n(input[static_cast<int>(i) % input_channels], frames, block_[sound[i]]);
    }
    // The block's channels, with each output's vibration in place.
    const float* const* compose(const float* const* vibration, int frames) {
        for (size_t k = 0; k < layout_.outputs.size(); ++k)
            std::copy_n(vibration[k], frames, block_[layout_.outputs[k].channel]);
        return block_.data();
    }

  private:
    const Layout& layout_;
    ChannelBlock block_;
};

}  // namespace tactus
