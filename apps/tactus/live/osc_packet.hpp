// OSC packets as they arrive on the network: a message, or a bundle of messages and bundles
// (OSC 1.0), decoded with liblo's parser into OscMessages. Time tags are not honoured: a
// bundle's messages apply on arrival.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "osc_address_space.hpp"

namespace tactus::live {

// Throws std::invalid_argument with one line for a malformed packet (nothing of it applies).
std::vector<OscMessage> decode_osc_packet(std::span<const std::byte> packet);
// One message as a packet (liblo's serialiser): numbers as their type says ('f', 'd', 'i'),
// text as 's'.
std::vector<std::byte> encode_osc_message(const OscMessage& message);

}  // namespace tactus::live
