// The recordings the tests read, from Debian's sonic-pi-samples (scripts/setup.sh installs it).
#pragma once

#include <string>

namespace tactus::test {

// The Amen break as Sonic Pi ships it: 6.9 s, 44.1 kHz stereo FLAC.
inline const std::string kAmen = "/usr/share/sonic-pi/samples/loop_amen_full.flac";

}  // namespace tactus::test
