// libFuzzer target: any bytes as one `--set key=value` argument. It either applies or throws
// std::invalid_argument with a one-line message; the settings stay inside the table's ranges.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "fuzz_check.hpp"
#include "tactus/io/preset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    tactus::Settings settings;
    const std::string_view assignment(reinterpret_cast<const char*>(data), size);
    try {
        tactus::apply_assignment(settings, assignment);
    } catch (const std::invalid_argument& e) {
        tactus::fuzz::check_message(e.what());
    }
    tactus::fuzz::check_in_range(settings);
    return 0;
}
