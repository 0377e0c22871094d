// Small helpers shared by the commands.
#pragma once

#include <fmt/format.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace tactus::cli {

// Refuses an output path that names the input file itself: inputs are never overwritten.
inline void refuse_overwriting_input(const std::filesystem::path& input,
                                     const std::filesystem::path& output) {
    std::error_code error;
    if (std::filesystem::equivalent(input, output, error))
        throw std::runtime_error(
            fmt::format("{}: output would overwrite the input file", output.string()));
}

}  // namespace tactus::cli
