// Which MPEG files state their length (io/mpeg_length_tag.hpp), on first frames built from the
// header layout (ISO/IEC 11172-3 and 13818-3) and the tags' published layouts: Xing/Info after
// the side information (its size by version and channel mode), VBRI 32 bytes after the header.
#include "tactus/io/mpeg_length_tag.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

namespace tactus {
namespace {

// A 1 KiB first frame: `header` (4 bytes), `tag` at `at`, then the tag's 4 flag bytes.
std::vector<unsigned char> frame(std::vector<unsigned char> header, const char* tag, size_t at,
                                 unsigned char flags = 0x0F) {
    std::vector<unsigned char> bytes(1024, 0);
    std::copy(header.begin(), header.end(), bytes.begin());
    std::memcpy(bytes.data() + at, tag, 4);
    bytes[at + 7] = flags;
    return bytes;
}

TEST(MpegLengthTag, XingOrInfoAfterTheSideInformationWithItsFrameCount) {
    const std::vector<unsigned char> mpeg1_stereo{0xFF, 0xFB, 0x90, 0x44};  // 128 kbps, 44.1 kHz
    const std::vector<unsigned char> mpeg1_mono{0xFF, 0xFB, 0x90, 0xC4};
    const std::vector<unsigned char> mpeg2_stereo{0xFF, 0xF3, 0x90, 0x64};  // 80 kbps, 22.05 kHz
    const std::vector<unsigned char> mpeg2_mono{0xFF, 0xF3, 0x90, 0xC4};
    EXPECT_TRUE(mpeg_tag_states_length(frame(mpeg1_stereo, "Xing", 4 + 32)));
    EXPECT_TRUE(mpeg_tag_states_length(frame(mpeg1_stereo, "Info", 4 + 32)));
    EXPECT_TRUE(mpeg_tag_states_length(frame(mpeg1_mono, "Info", 4 + 17)));
    EXPECT_TRUE(mpeg_tag_states_length(frame(mpeg2_stereo, "Info", 4 + 17)));
    EXPECT_TRUE(mpeg_tag_states_length(frame(mpeg2_mono, "Xing", 4 + 9)));
    // With a CRC, two bytes later.
    EXPECT_TRUE(mpeg_tag_states_length(frame({0xFF, 0xFA, 0x90, 0x44}, "Xing", 4 + 2 + 32)));
    // Without the frame-count flag the tag states no length; a tag elsewhere is not one.
    EXPECT_FALSE(mpeg_tag_states_length(frame(mpeg1_stereo, "Xing", 4 + 32, 0x0E)));
    EXPECT_FALSE(mpeg_tag_states_length(frame(mpeg1_stereo, "Info", 4 + 17)));
    EXPECT_FALSE(mpeg_tag_states_length(frame(mpeg2_mono, "Xing", 4 + 17)));
    EXPECT_FALSE(mpeg_tag_states_length(frame(mpeg1_stereo, "none", 4 + 32)));
}

TEST(MpegLengthTag, VbriThirtyTwoBytesAfterTheHeader) {
    EXPECT_TRUE(mpeg_tag_states_length(frame({0xFF, 0xFB, 0x90, 0xC4}, "VBRI", 36)));
    EXPECT_FALSE(mpeg_tag_states_length(frame({0xFF, 0xFB, 0x90, 0xC4}, "VBRI", 40)));
}

TEST(MpegLengthTag, NotAnMpegLayerThreeFrame) {
    EXPECT_FALSE(mpeg_tag_states_length(frame({0xFF, 0xFD, 0x90, 0x44}, "Xing", 36)));  // layer II
    EXPECT_FALSE(mpeg_tag_states_length(frame({0xFF, 0xEB, 0x90, 0x44}, "Xing", 36)));  // reserved
    EXPECT_FALSE(mpeg_tag_states_length(frame({'R', 'I', 'F', 'F'}, "Xing", 36)));
    EXPECT_FALSE(mpeg_tag_states_length({}));
}

}  // namespace
}  // namespace tactus
