// libFuzzer target: any bytes as a preset's TOML text. A preset either applies or throws
// std::runtime_error with a one-line message; anything else (crash, other exception, a
// sanitizer report, a value outside its table range, settings that preset_text() does not
// write back bit for bit) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include "fuzz_check.hpp"
#include "tactus/io/preset.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    tactus::Settings settings;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        tactus::apply_preset_text(settings, text, "fuzz.toml");
    } catch (const std::runtime_error& e) {
        tactus::fuzz::check_message(e.what());
    }
    tactus::fuzz::check_in_range(settings);
    tactus::Settings again;
    tactus::apply_preset_text(again, tactus::preset_text(settings, "state"), "state.toml");
    if (!tactus::fuzz::same_bits(settings, again)) std::abort();
    return 0;
}
