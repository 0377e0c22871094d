// User text quoted in an error message: control characters become escapes (\n, \t, \xHH), so
// every message stays on one line whatever was typed or read.
#pragma once

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace tactus {

inline std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\n')
            out += "\\n";
        else if (c == '\t')
            out += "\\t";
        else if (c == '\r')
            out += "\\r";
        else if (byte < 0x20 || byte == 0x7f)
            out += fmt::format("\\x{:02x}", byte);
        else
            out += c;
    }
    return out;
}

}  // namespace tactus
