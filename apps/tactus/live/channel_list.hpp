// Device channel lists as the command line gives them: "1,2,5" or "1-4", counted from 1.
#pragma once

#include <string>
#include <vector>

namespace tactus::live {

// Channels counted from 0; throws std::invalid_argument naming `option` for anything else.
std::vector<int> parse_channel_list(const std::string& text, const std::string& option);

}  // namespace tactus::live
