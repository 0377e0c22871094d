// Device channels as the command line gives them, counted from 1: lists ("1,2,5" or "1-4") and
// one device's channel ("DEV:CH").
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tactus::live {

// Channels counted from 0; throws std::invalid_argument naming `option` for anything else.
std::vector<int> parse_channel_list(const std::string& text, const std::string& option);

// "DEV:CH": the device and its channel counted from 0. Without a number after the last colon the
// whole text is the device and the channel is -1 (all of them) when `channel_optional`; otherwise
// throws std::invalid_argument naming `option`.
std::pair<std::string, int> parse_device_channel(const std::string& text, const std::string& option,
                                                 bool channel_optional);

}  // namespace tactus::live
