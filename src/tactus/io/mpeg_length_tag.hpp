// Whether an MPEG audio file states its length. An encoder that knows it writes a Xing or Info
// tag (LAME and most encoders) or a VBRI tag (Fraunhofer) into the first frame, with the frame
// count; libmpg123 (and so libsndfile's SF_INFO.frames) then reports that exact length. Without
// one, the length is estimated from the file's size and the first frame's size, and a constant
// bitrate file's padded frames (one byte longer than the first, unpadded one) or trailing bytes
// make it exceed what decodes (a 4.8 min 80 kbps file by 5510 frames): an estimate, not a promise.
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>

namespace tactus {

// `start`: the file's first bytes from its first MPEG frame on (after any ID3v2 tags); true if
// that frame is layer III and carries a Xing or Info tag with a frame count, or a VBRI tag.
bool mpeg_tag_states_length(std::span<const unsigned char> start);

// The same for an open file: skips its ID3v2 tags and any junk up to the first frame header
// (reading with pread, so the descriptor's offset is left as it was).
bool mpeg_file_states_length(int fd);

}  // namespace tactus
