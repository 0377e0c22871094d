#include "channel_list.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>

#include "tactus/core/printable.hpp"

namespace tactus::live {
namespace {

constexpr int kMaxChannel = 1024;

int channel(const std::string& text, const std::string& option, const std::string& all) {
    int c = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), c);
    if (error != std::errc() || end != text.data() + text.size() || c < 1 || c > kMaxChannel)
        throw std::invalid_argument(
            fmt::format("{} {}: channels are numbers from 1 to {}, as in 1,2 or 1-4", option,
                        printable(all), kMaxChannel));
    return c - 1;
}

}  // namespace

std::vector<int> parse_channel_list(const std::string& text, const std::string& option) {
    std::vector<int> channels;
    std::istringstream parts(text);
    for (std::string part; std::getline(parts, part, ',');) {
        if (const size_t dash = part.find('-'); dash != std::string::npos) {
            const int from = channel(part.substr(0, dash), option, text);
            const int to = channel(part.substr(dash + 1), option, text);
            if (to < from)
                throw std::invalid_argument(
                    fmt::format("{} {}: a range goes upwards", option, printable(text)));
            for (int c = from; c <= to; ++c) channels.push_back(c);
        } else {
            channels.push_back(channel(part, option, text));
        }
    }
    if (channels.empty()) throw std::invalid_argument(fmt::format("{}: no channel given", option));
    std::vector<int> sorted = channels;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        throw std::invalid_argument(
            fmt::format("{} {}: a channel is named twice", option, printable(text)));
    return channels;
}

std::pair<std::string, int> parse_device_channel(const std::string& text, const std::string& option,
                                                 bool channel_optional) {
    const size_t colon = text.rfind(':');
    const bool numbered = colon != std::string::npos && colon > 0 && colon + 1 < text.size() &&
                          text.find_first_not_of("0123456789", colon + 1) == std::string::npos;
    if (numbered)
        return {text.substr(0, colon), parse_channel_list(text.substr(colon + 1), option)[0]};
    if (channel_optional) return {text, -1};
    throw std::invalid_argument(
        fmt::format("{} {}: give DEV:CH (CH from 1)", option, printable(text)));
}

}  // namespace tactus::live
