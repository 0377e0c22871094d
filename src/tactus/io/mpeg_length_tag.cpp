#include "tactus/io/mpeg_length_tag.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace tactus {
namespace {

// An MPEG audio frame header (ISO/IEC 11172-3 2.4.1.3, 13818-3 2.4.1.3): 11 sync bits,
// version, layer, protection, bitrate, sample rate, padding, private, channel mode.
struct FrameHeader {
    bool mpeg1 = false, layer3 = false, crc = false, mono = false;
};

bool parse_header(const unsigned char* b, FrameHeader& h) {
    if (b[0] != 0xFF || (b[1] & 0xE0) != 0xE0) return false;
    const int version = (b[1] >> 3) & 3, layer = (b[1] >> 1) & 3;
    const int bitrate = b[2] >> 4, rate = (b[2] >> 2) & 3;
    if (version == 1 || layer == 0 || bitrate == 15 || rate == 3) return false;  // reserved
    h = {.mpeg1 = version == 3,
         .layer3 = layer == 1,
         .crc = (b[1] & 1) == 0,
         .mono = (b[3] >> 6) == 3};
    return true;
}

bool tag_at(std::span<const unsigned char> frame, size_t at, const char* name) {
    return frame.size() >= at + 4 && std::memcmp(frame.data() + at, name, 4) == 0;
}

// An ID3v2 tag's whole size (header, body and footer), or 0 if `b` does not start one.
size_t id3v2_size(const unsigned char* b) {
    if (std::memcmp(b, "ID3", 3) != 0) return 0;
    const size_t body = (size_t{b[6]} & 0x7F) << 21 | (size_t{b[7]} & 0x7F) << 14 |
                        (size_t{b[8]} & 0x7F) << 7 | (size_t{b[9]} & 0x7F);  // syncsafe
    constexpr size_t kHeader = 10;
    return kHeader + body + ((b[5] & 0x10) ? kHeader : 0);  // the footer flag
}

}  // namespace

bool mpeg_tag_states_length(std::span<const unsigned char> start) {
    FrameHeader h;
    if (start.size() < 4 || !parse_header(start.data(), h) || !h.layer3) return false;
    // The Xing tag follows the side information (17 or 32 bytes in MPEG-1, 9 or 17 in MPEG-2
    // and 2.5), after the CRC if there is one; its flags' bit 0 says the frame count is there.
    const size_t side_info = h.mpeg1 ? (h.mono ? 17 : 32) : (h.mono ? 9 : 17);
    const size_t xing = 4 + (h.crc ? 2 : 0) + side_info;
    if ((tag_at(start, xing, "Xing") || tag_at(start, xing, "Info")) && start.size() >= xing + 8)
        return (start[xing + 7] & 1) != 0;
    constexpr size_t kVbri = 4 + 32;  // always 32 bytes after the header; always has the count
    return tag_at(start, kVbri, "VBRI");
}

bool mpeg_file_states_length(int fd) {
    off_t offset = 0;
    std::array<unsigned char, 10> id3{};
    while (::pread(fd, id3.data(), id3.size(), offset) == static_cast<ssize_t>(id3.size())) {
        const size_t size = id3v2_size(id3.data());
        if (size == 0) break;
        offset += static_cast<off_t>(size);
    }
    // libmpg123 looks this far for the first frame too (it gives up after 64 KiB of junk).
    constexpr size_t kSearch = size_t{64} * 1024, kFrame = 2048;
    std::vector<unsigned char> bytes(kSearch + kFrame);
    const ssize_t got = ::pread(fd, bytes.data(), bytes.size(), offset);
    if (got < 4) return false;
    const std::span<const unsigned char> read(bytes.data(), static_cast<size_t>(got));
    FrameHeader h;
    for (size_t at = 0; at + 4 <= std::min(read.size(), kSearch); ++at)
        if (parse_header(read.data() + at, h)) return mpeg_tag_states_length(read.subspan(at));
    return false;
}

}  // namespace tactus
